#pragma once
// The stability suite's cases and the one function that decides each technique's error bound on
// each case (the documented rules of boundRules(), made concrete).

#include "parallax/eval/StabilitySuite.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/sample/ProceduralMaps.h"

#include <glm/vec2.hpp>
#include <vector>

namespace px::stability {

enum class Reference {
    Exact,      // the `exact` technique's hits
    ClosedForm, // a constant surface: t = 1 - h, checked against exact too
};

enum class Special {
    None,
    FarOrigin,     // uv0 shifted by whole tiles: compared with the same rays near the origin
    ZeroCones,     // cone maps of zeros: the cone marches must fall back to cell steps
    ForeignCones,  // cone maps baked from another height map
    NanInFloatMap, // a float file with a NaN texel must be rejected by the loader
};

// One view of a case's rays: polar and azimuth angles, degrees.
struct View {
    double polarDeg = 60.0;
    double azimuthDeg = 35.0;
};

struct CaseSpec {
    StabilityCaseInfo info;
    ProceduralMap map = ProceduralMap::Noise;
    int width = 32;
    int height = 32;
    float level = 0.0f; // flat maps
    WrapMode wrap = WrapMode::Repeat;
    float scale = 0.1f;
    double polarDeg = 60.0;
    double azimuthDeg = 35.0;
    Reference reference = Reference::Exact;
    // Width at half height of the narrowest raised feature a ray can pass over, in texels: a
    // march whose layers are longer than half of it may step over features (Nyquist). Noise:
    // its second octave; a single raised texel: one texel.
    double featureTexels = 1.0;
    Special special = Special::None;
    glm::dvec2 uvOffset{0.0, 0.0};
    // More views whose rays are pooled into the case's rows (the adversarial maps); empty: the
    // one view above.
    std::vector<View> views;
};

// The views a case traces: its `views`, or its one polar and azimuth.
std::vector<View> caseViews(const CaseSpec& spec);

std::span<const CaseSpec> caseSpecs();

// What the bound rules need to know about a case's rays.
struct CaseGeometry {
    double rayTexels = 0.0; // length of the ray's footprint below the highest texel, in texels
    double rayTiles = 0.0;  // the same in uv units (tiles)
    double cosTheta = 1.0;
};

ErrorBound boundFor(const CaseSpec& spec, Technique technique, const TraceParams& params,
                    const CaseGeometry& geometry);

} // namespace px::stability

#pragma once
// The techniques of docs/techniques.md, their names, what they read and their
// parameters (the ones artists know from the tutorial shaders).

#include <optional>
#include <span>
#include <string_view>

namespace px {

enum class Technique {
    None,
    Normal,
    Offset,
    Steep,
    Pom,
    Relief,
    Secant,
    Cone,
    RelaxedCone,
    Pyramid,
    Exact
};

// Parameters every technique understands; each reads the ones its info() lists.
struct TraceParams {
    int minLayers = 8;   // layers looking straight down (the tutorials' quality range)
    int maxLayers = 32;  // layers at grazing angles
    int binarySteps = 6; // relief's refinement halvings
    int secantSteps = 3; // secant refinement steps
    int maxSteps = 64;   // hard cap on the main loop: cone steps, cells, pyramid nodes
};

struct TechniqueInfo {
    Technique id;
    std::string_view name;  // as on the command line and in materials
    std::string_view title; // for people
    bool parallax;          // offsets the uv (false: none, normal)
    bool usesLayers;
    bool usesBinarySteps;
    bool usesSecantSteps;
    bool usesMaxSteps;
    bool needsConeMap;
    bool needsRelaxedConeMap;
    bool needsPyramid;
    TraceParams defaults;
};

std::span<const TechniqueInfo> allTechniques();
const TechniqueInfo& info(Technique technique);
std::optional<Technique> parseTechnique(std::string_view name);

// The most fetches one ray may cost with these parameters: every kernel loop is capped, and this
// is the contract the stability tests hold them to. `rayCells` bounds the cells the ray crosses
// (rayCellBound() in TraceScene.h): `cone`, `relaxed-cone` and `pyramid` finish a ray their cap
// or their last step leaves open with an exact walk over those cells.
long long fetchCap(Technique technique, const TraceParams& params, long long rayCells);

// The refinement steps the kernel uses for this technique (binary or secant, else 0).
int refineSteps(Technique technique, const TraceParams& params);

// Limits the command line and material loader enforce (and the kernels rely on).
inline constexpr int kMaxLayersLimit = 4096;
inline constexpr int kMaxRefineLimit = 64;
inline constexpr int kMaxStepsLimit = 1 << 24;

} // namespace px

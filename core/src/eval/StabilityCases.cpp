#include "StabilityCases.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace px::stability {
namespace {

using enum ProceduralMap;

// Value noise's second octave has 8 cells across the tile: its bumps are W/8 texels wide.
double noiseFeature(int width) {
    return width / 8.0;
}

CaseSpec make(std::string_view name, std::string_view what, ProceduralMap map, int w, int h,
              float scale, double polar, double azimuth) {
    CaseSpec c;
    c.info = {name, what};
    c.map = map;
    c.width = w;
    c.height = h;
    c.scale = scale;
    c.polarDeg = polar;
    c.azimuthDeg = azimuth;
    switch (map) {
    case Noise:
        c.featureTexels = noiseFeature(w);
        break;
    case Step:
        c.featureTexels = w / 2.0; // one wall, the high half behind it
        break;
    case Cracks:
        c.featureTexels = 4.0; // plateaus between cracks: at least 4 texels
        break;
    default:
        c.featureTexels = 1.0; // single texels: checker, needles, random
        break;
    }
    return c;
}

CaseSpec with(CaseSpec c, auto&& edit) {
    edit(c);
    return c;
}

// The maps made to break each technique, at the grazing views where caps bind and brackets span
// several features: every ray of every view is held to the technique's bound.
void addAdversarial(std::vector<CaseSpec>& cases) {
    struct Class {
        std::string_view name, repeatName, clampName, what;
        ProceduralMap map;
        int width, height;
    };
    static constexpr Class kClasses[] = {
        {"spike-flat", "adversarial-spike-flat", "adversarial-spike-flat-clamp",
         "a long 256 x 8 strip: flats ending in one single-texel spike per row", SpikeFlat, 256, 8},
        {"walls", "adversarial-walls", "adversarial-walls-clamp",
         "one-texel walls every second column (the Nyquist rate)", Walls, 64, 64},
        {"treads", "adversarial-treads", "adversarial-treads-clamp",
         "stairs with treads 8 to 32 texels long", Treads, 64, 64},
        {"pits", "adversarial-pits", "adversarial-pits-clamp",
         "the top pierced by isolated one-texel pits to the bottom", Pits, 64, 64},
        {"terraces", "adversarial-terraces", "adversarial-terraces-clamp",
         "smooth hills cut into 8-bit quantised terraces", Terraces, 64, 64},
        {"outliers", "adversarial-outliers", "adversarial-outliers-clamp",
         "gentle low noise with six single texels at the top", Outliers, 64, 64},
        {"jpeg", "adversarial-jpeg", "adversarial-jpeg-clamp",
         "ridged terrain with grain, 8 bits, through a JPEG codec at quality 75", Jpeg, 64, 64},
    };
    std::vector<View> views;
    for (double polar : {80.0, 87.0, 89.0}) {
        for (double azimuth : {0.0, 35.0, 45.0, 90.0})
            views.push_back({polar, azimuth});
    }
    for (const Class& k : kClasses) {
        for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
            CaseSpec c = make(wrap == WrapMode::Repeat ? k.repeatName : k.clampName, k.what, k.map,
                              k.width, k.height, 0.1f, 89.0, 0.0);
            c.wrap = wrap;
            c.featureTexels = 1.0;
            c.views = views;
            cases.push_back(c);
        }
    }
}

const std::vector<CaseSpec>& specs() {
    static const std::vector<CaseSpec> cases = {
        make("polar-89.9", "a view 0.1 degree above the surface: rays ~1800 texels long", Noise, 32,
             32, 0.1f, 89.9, 35),
        with(make("polar-89.9-clamp", "the same with clamp: rays leave the tile", Noise, 32, 32,
                  0.1f, 89.9, 35),
             [](CaseSpec& c) { c.wrap = WrapMode::Clamp; }),
        make("scale-0", "height scale 0: every technique costs one fetch, t = 1 - h(uv0)", Noise,
             32, 32, 0.0f, 80, 35),
        make("tiny-scale", "height scale 1e-6: rays shorter than a thousandth of a texel", Noise,
             32, 32, 1e-6f, 80, 35),
        make("huge-scale", "height scale 10 (relief 10 tiles deep): rays ~280 texels long", Noise,
             16, 16, 10.0f, 60, 35),
        with(make("flat-0", "a flat map at 0: every ray ends at the bottom, t = 1", Flat, 16, 16,
                  0.1f, 80, 35),
             [](CaseSpec& c) {
                 c.level = 0.0f;
                 c.reference = Reference::ClosedForm;
             }),
        with(make("flat-1", "a flat map at 1: every ray stops at the top, t = 0", Flat, 16, 16,
                  0.1f, 80, 35),
             [](CaseSpec& c) {
                 c.level = 1.0f;
                 c.reference = Reference::ClosedForm;
             }),
        make("checkerboard", "a 0/1 checkerboard of single texels", Checker, 32, 32, 0.1f, 80, 35),
        make("needles", "sparse single-texel needles of height 1 on 0", Spikes, 64, 64, 0.1f, 85,
             35),
        make("vertical-steps", "a 0 to 1 step, rays running into the wall", Step, 32, 32, 0.2f, 87,
             0),
        with(make("vertical-steps-clamp", "the same with clamp", Step, 32, 32, 0.2f, 87, 180),
             [](CaseSpec& c) { c.wrap = WrapMode::Clamp; }),
        make("thin-cracks", "flat 1 with one-texel cracks down to 0", Cracks, 64, 64, 0.1f, 80, 0),
        with(make("1x1", "a one-texel map: a constant surface", Random, 1, 1, 0.1f, 70, 35),
             [](CaseSpec& c) { c.reference = Reference::ClosedForm; }),
        make("non-power-of-two", "a 23 x 17 map of random texels", Random, 23, 17, 0.3f, 85, 120),
        with(make("non-power-of-two-clamp", "the same with clamp", Random, 23, 17, 0.3f, 85, 120),
             [](CaseSpec& c) { c.wrap = WrapMode::Clamp; }),
        with(make("uv0-near-4096", "uv0 4096 tiles from the origin (float keeps ~5e-4 there)",
                  Noise, 32, 32, 0.1f, 60, 35),
             [](CaseSpec& c) {
                 c.special = Special::FarOrigin;
                 c.uvOffset = {4096.0, 4095.0};
             }),
        with(make("zero-cones", "cone maps of zeros: the marches must not stall", Noise, 32, 32,
                  0.05f, 60, 35),
             [](CaseSpec& c) { c.special = Special::ZeroCones; }),
        with(make("nan-in-float-map", "a float EXR with a NaN texel must be refused, with where",
                  Flat, 8, 8, 0.1f, 60, 35),
             [](CaseSpec& c) { c.special = Special::NanInFloatMap; }),
        with(make("foreign-cone-map", "the cone maps of a flat map (the widest cones) on noise",
                  Noise, 32, 32, 0.1f, 70, 35),
             [](CaseSpec& c) { c.special = Special::ForeignCones; }),
    };
    static const std::vector<CaseSpec> all = [] {
        std::vector<CaseSpec> v = cases;
        addAdversarial(v);
        return v;
    }();
    return all;
}

// The documented rules. boundFor() below is their only implementation.
constexpr std::array kRules{
    BoundRule{Technique::Offset, "no accuracy bound: one fetch, t = (1 - h(uv0)) cos(polar)"},
    BoundRule{Technique::Steep,
              "p99 within one layer (ray length / layers) of the hit where layers are at most half "
              "as long as the map's features (Nyquist); none where longer (features get stepped "
              "over)"},
    BoundRule{Technique::Pom, "as steep"},
    BoundRule{Technique::Relief, "as steep"},
    BoundRule{Technique::Secant, "as steep"},
    BoundRule{Technique::Cone,
              "exact: every ray within 0.05 texel of exact (a march its step cap stops is finished "
              "by the exact cell walk)"},
    BoundRule{Technique::RelaxedCone,
              "exact: every ray within 0.05 texel of exact (each step stays inside the relaxed "
              "cones of a triangle of texels around the ray, so it cannot leave the solid; the "
              "last step and a capped march are solved exactly)"},
    BoundRule{Technique::Pyramid, "exact: every ray within 0.05 texel of exact"},
    BoundRule{Technique::Exact, "the reference: within 0.001 texel of the closed forms"},
};

// As the kernel counts layers (pxLayerCount), rounded down: a conservative spacing.
double layerCount(const TraceParams& params, const CaseGeometry& geometry) {
    return std::max(1.0, std::floor(params.maxLayers +
                                    (params.minLayers - params.maxLayers) * geometry.cosTheta));
}

std::string texels(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

} // namespace

std::span<const CaseSpec> caseSpecs() {
    return specs();
}

std::vector<View> caseViews(const CaseSpec& spec) {
    if (!spec.views.empty())
        return spec.views;
    return {View{spec.polarDeg, spec.azimuthDeg}};
}

ErrorBound boundFor(const CaseSpec& spec, Technique t, const TraceParams& params,
                    const CaseGeometry& geometry) {
    // Cases that change what the techniques can promise come first.
    switch (spec.special) {
    case Special::FarOrigin:
        return {BoundKind::MaxTexels, 0.01,
                "far-tiled uv: the same hit as near the origin, shifted by whole tiles"};
    case Special::ZeroCones:
        return {BoundKind::MaxTexels, 0.05,
                "zero cones fall back to exact cell steps (these rays cross fewer cells than the "
                "cap)"};
    case Special::ForeignCones:
        return {BoundKind::None, 0.0, "a cone map of another height map voids every cone bound"};
    case Special::NanInFloatMap:
    case Special::None:
        break;
    }
    if (spec.scale == 0.0f)
        return {BoundKind::MaxDepth, 1e-6, "height scale 0: t = 1 - h(uv0) at one fetch"};
    if (spec.reference == Reference::ClosedForm && t == Technique::Steep) {
        // Steep returns the first layer at or below the surface, refined by nothing: on a
        // constant surface that is within one layer, exact only where a layer falls on it.
        const double spacing = geometry.rayTexels / layerCount(params, geometry);
        return {BoundKind::MaxTexels, std::max(spacing, 1e-3),
                "a constant surface, within one layer: " + texels(spacing) + " texels"};
    }
    if (spec.reference == Reference::ClosedForm && t != Technique::Offset)
        return {BoundKind::MaxTexels, 1e-3, "a constant surface is found exactly"};

    switch (t) {
    case Technique::Offset:
        return {BoundKind::None, 0.0, std::string(kRules[0].rule)};
    case Technique::Steep:
    case Technique::Pom:
    case Technique::Relief:
    case Technique::Secant: {
        const double layers = layerCount(params, geometry);
        const double spacing = geometry.rayTexels / layers;
        if (spacing > 0.5 * spec.featureTexels)
            return {BoundKind::None, 0.0,
                    "layers of " + texels(spacing) + " texels can step over " +
                        texels(spec.featureTexels) + "-texel features"};
        return {BoundKind::P99Texels, std::max(spacing, 1e-3),
                "within one layer: " + texels(geometry.rayTexels) + " texels / " + texels(layers) +
                    " layers"};
    }
    case Technique::Cone:
    case Technique::RelaxedCone:
    case Technique::Pyramid:
        return {BoundKind::MaxTexels, kExactTexels, "documented exact"};
    case Technique::Exact:
        return {BoundKind::None, 0.0, "the reference itself"};
    case Technique::None:
    case Technique::Normal:
        break;
    }
    return {BoundKind::None, 0.0, "traces no rays"};
}

} // namespace px::stability

namespace px {

std::span<const StabilityCaseInfo> stabilityCases() {
    static const std::vector<StabilityCaseInfo> infos = [] {
        std::vector<StabilityCaseInfo> v;
        for (const stability::CaseSpec& c : stability::caseSpecs())
            v.push_back(c.info);
        return v;
    }();
    return infos;
}

std::span<const BoundRule> boundRules() {
    return stability::kRules;
}

} // namespace px

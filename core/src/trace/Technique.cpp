#include "parallax/trace/Technique.h"

#include <array>

namespace px {
namespace {

constexpr TraceParams layered(int minLayers, int maxLayers) {
    TraceParams p;
    p.minLayers = minLayers;
    p.maxLayers = maxLayers;
    return p;
}

constexpr TraceParams capped(int maxSteps) {
    TraceParams p;
    p.maxSteps = maxSteps;
    p.binarySteps = 0; // not read: kept 0 so that saved materials do not suggest otherwise
    return p;
}

// clang-format off
constexpr std::array kTechniques{
    //           id                      name            title                              parallax layers binary secant maxSteps cone  relaxed pyramid defaults
    TechniqueInfo{Technique::None,        "none",         "No parallax",                     false, false, false, false, false, false, false, false, TraceParams{}},
    TechniqueInfo{Technique::Normal,      "normal",       "Normal mapping",                  false, false, false, false, false, false, false, false, TraceParams{}},
    TechniqueInfo{Technique::Offset,      "offset",       "Parallax with offset limiting",   true,  false, false, false, false, false, false, false, TraceParams{}},
    TechniqueInfo{Technique::Steep,       "steep",        "Steep parallax",                  true,  true,  false, false, false, false, false, false, layered(8, 32)},
    TechniqueInfo{Technique::Pom,         "pom",          "Parallax occlusion mapping",      true,  true,  false, false, false, false, false, false, layered(8, 32)},
    TechniqueInfo{Technique::Relief,      "relief",       "Relief mapping (binary search)",  true,  true,  true,  false, false, false, false, false, layered(8, 32)},
    TechniqueInfo{Technique::Secant,      "secant",       "Secant refinement",               true,  true,  false, true,  false, false, false, false, layered(8, 32)},
    TechniqueInfo{Technique::Cone,        "cone",         "Cone step mapping",               true,  false, false, false, true,  true,  false, false, capped(128)},
    TechniqueInfo{Technique::RelaxedCone, "relaxed-cone", "Relaxed cone stepping",           true,  false, false, false, true,  false, true,  false, capped(64)},
    TechniqueInfo{Technique::Pyramid,     "pyramid",      "Pyramidal (max-mip) displacement",true,  false, false, false, true,  false, false, true,  capped(1 << 16)},
    TechniqueInfo{Technique::Exact,       "exact",        "Exact intersection (reference)",  true,  false, false, false, true,  false, false, false, capped(1 << 22)},
};
// clang-format on

} // namespace

std::span<const TechniqueInfo> allTechniques() {
    return kTechniques;
}

const TechniqueInfo& info(Technique technique) {
    for (const TechniqueInfo& t : kTechniques) {
        if (t.id == technique)
            return t;
    }
    return kTechniques[0];
}

std::optional<Technique> parseTechnique(std::string_view name) {
    for (const TechniqueInfo& t : kTechniques) {
        if (t.name == name)
            return t.id;
    }
    return std::nullopt;
}

long long fetchCap(Technique t, const TraceParams& p, long long rayCells) {
    switch (t) {
    case Technique::None:
    case Technique::Normal:
        return 0;
    case Technique::Offset:
        return 1;
    case Technique::Steep:
    case Technique::Pom:
        return p.maxLayers + 1; // layers 0..n, n <= maxLayers
    case Technique::Relief:
        return p.maxLayers + 1 + p.binarySteps;
    case Technique::Secant:
        return p.maxLayers + 1 + p.secantSteps;
    // The cone marches and the pyramid end with at most one exact walk over part of the ray.
    case Technique::Cone:        // one gather of the cell's corner cones per step
    case Technique::RelaxedCone: // the same
        return p.maxSteps + rayCells;
    case Technique::Pyramid: // a node and a cell solve per step
        return 2LL * p.maxSteps + rayCells;
    case Technique::Exact:
        return p.maxSteps; // one gather per cell
    }
    return 0;
}

int refineSteps(Technique technique, const TraceParams& params) {
    const TechniqueInfo& i = info(technique);
    if (i.usesBinarySteps)
        return params.binarySteps;
    if (i.usesSecantSteps)
        return params.secantSteps;
    return 0;
}

} // namespace px

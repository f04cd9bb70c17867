#include "model/DocumentState.h"

#include <algorithm>

namespace px::studio {

bool sameParams(const TraceParams& a, const TraceParams& b) {
    return a.minLayers == b.minLayers && a.maxLayers == b.maxLayers &&
           a.binarySteps == b.binarySteps && a.secantSteps == b.secantSteps &&
           a.maxSteps == b.maxSteps;
}

bool operator==(const ViewQuality& a, const ViewQuality& b) {
    return a.technique == b.technique && sameParams(a.params, b.params);
}

std::array<ViewQuality, kMaxViewports> defaultComparisonViews() {
    std::array<ViewQuality, kMaxViewports> views;
    const Technique order[kMaxViewports] = {Technique::Pom, Technique::Relief, Technique::Pyramid,
                                            Technique::Exact};
    for (int i = 0; i < kMaxViewports; ++i)
        views[static_cast<std::size_t>(i)] = {order[i], info(order[i]).defaults};
    return views;
}

ViewQuality DocumentState::view(int index) const {
    if (index <= 0)
        return {material.technique, material.params};
    return views[static_cast<std::size_t>(std::min(index, kMaxViewports - 1))];
}

void DocumentState::setView(int index, const ViewQuality& quality) {
    if (index <= 0) {
        // A technique or quality set by hand replaces "auto" (TechniquePanel sets auto's choice
        // on the material directly).
        material.technique = quality.technique;
        material.params = quality.params;
        material.autoQuality.reset();
    } else if (index < kMaxViewports) {
        views[static_cast<std::size_t>(index)] = quality;
    }
}

bool DocumentState::anyUnsaved() const {
    return std::any_of(unsaved.begin(), unsaved.end(), [](bool u) { return u; });
}

bool DocumentState::hasMap(MapKind kind) const {
    const MaterialAssets& a = *assets;
    switch (kind) {
    case MapKind::Albedo:
        return !a.albedo.empty();
    case MapKind::Height:
        return !a.height.empty();
    case MapKind::Normal:
        return !a.normal.empty();
    case MapKind::Cone:
        return a.cone.width > 0;
    case MapKind::RelaxedCone:
        return a.relaxedCone.width > 0;
    case MapKind::Ao:
        return !a.ao.empty();
    case MapKind::Roughness:
        return !a.roughness.empty();
    case MapKind::Metallic:
        return !a.metallic.empty();
    case MapKind::Specular:
        return !a.specular.empty();
    }
    return false;
}

bool DocumentState::canTrace(Technique technique) const {
    const TechniqueInfo& t = info(technique);
    if (t.parallax && !hasMap(MapKind::Height))
        return false;
    if (t.needsConeMap && !hasMap(MapKind::Cone))
        return false;
    if (t.needsRelaxedConeMap && !hasMap(MapKind::RelaxedCone))
        return false;
    return true;
}

} // namespace px::studio

#include "parallax/bake/ConeMapBaker.h"

#include "parallax/bake/ConeMapFinish.h"

namespace px {

Result<ConeMap> bakeConeMap(const HeightField& field, WrapMode wrap, ConeKind kind,
                            const BakeControl& control) {
    Result<ConeMap> cones = kind == ConeKind::Conservative
                                ? bakeQuickConeMap(field, wrap, control)
                                : bakeRelaxedConeMap(field, wrap, control);
    if (!cones)
        return cones;
    applyNeighbourhoodMinimum(*cones, wrap);
    return cones;
}

ConeMap bakeConeMap(const HeightField& field, WrapMode wrap, ConeKind kind) {
    Result<ConeMap> cones = bakeConeMap(field, wrap, kind, BakeControl{});
    return cones ? std::move(*cones) : ConeMap(kind, 0, 0);
}

} // namespace px

#include "parallax/bake/ConeMapBaker.h"

#include "parallax/bake/ConeMapReference.h"

namespace px {

ConeMap bakeConeMap(const HeightField& field, WrapMode wrap, ConeKind kind) {
    ConeMap cones = kind == ConeKind::Conservative ? bakeConservativeConesBruteForce(field, wrap)
                                                   : bakeRelaxedConesBruteForce(field, wrap);
    applyNeighbourhoodMinimum(cones, wrap);
    return cones;
}

} // namespace px

#pragma once
// The cone map bakers everything else calls (CONVENTIONS §4, CONE_MAPS.md).

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

namespace px {

// Bakes a conservative or relaxed cone map, 3x3-minimum post-processed, not quantised.
ConeMap bakeConeMap(const HeightField& field, WrapMode wrap, ConeKind kind);

} // namespace px

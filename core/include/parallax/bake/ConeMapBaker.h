#pragma once
// The cone map bakers everything else calls (docs/conventions.md §4, docs/cone-maps.md). All of
// them are for the bilinear surface, wrap or clamp as the material says, and use every core (TBB).
//
// Conservative: no point of the bilinear height field lies inside any texel's cone. Quick cone
// maps (Valasek & Bán 2022) over a maximum pyramid of the cells, Θ(N² log N); the cells around
// the apex are bounded exactly (the steepest secant from the apex), so cones are as wide as the
// definition allows there and never wider anywhere.
//
// Relaxed: a ray from the apex's column that stays in the cone never leaves the solid once it
// has entered it (Bán et al. 2024, corrected relaxed cones), made safe for the bilinear
// surface: a cell limits the cone wherever it falls away from the apex, at the cell's own
// exact bound rather than at its nearest corner's height.

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

namespace px {

// Raw bakes: per-texel cones, not post-processed, not quantised. Errors: an empty height field,
// cancellation (cancelledError()).
Result<ConeMap> bakeQuickConeMap(const HeightField& field, WrapMode wrap,
                                 const BakeControl& control = {});
Result<ConeMap> bakeRelaxedConeMap(const HeightField& field, WrapMode wrap,
                                   const BakeControl& control = {});

// What the techniques use: the raw bake of `kind`, then the 3x3 minimum (docs/cone-maps.md §1) that
// makes bilinearly interpolated cones safe. Not quantised (see ConeMapImage.h for files).
Result<ConeMap> bakeConeMap(const HeightField& field, WrapMode wrap, ConeKind kind,
                            const BakeControl& control);

// The same without progress or cancellation; an empty field gives an empty map.
ConeMap bakeConeMap(const HeightField& field, WrapMode wrap, ConeKind kind);

} // namespace px

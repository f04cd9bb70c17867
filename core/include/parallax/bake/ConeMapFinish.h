#pragma once
// What every cone map goes through after its bake, whichever baker made it: the 3x3 minimum and
// the rounding down to the stored precision.

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/WrapMode.h"

namespace px {

// Replaces each cone by the minimum over its 3x3 neighbourhood (wrap or clamp), which makes the
// bilinearly interpolated cone anywhere in a cell no wider than any of its corners' cones.
// In place, with memory for a few rows only.
void applyNeighbourhoodMinimum(ConeMap& cones, WrapMode wrap);

// Rounds each stored sqrt(ratio) down to `levels` steps (255 or 65535): never widens a cone.
void quantiseDown(ConeMap& cones, int levels);

} // namespace px

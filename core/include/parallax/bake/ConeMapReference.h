#pragma once
// Brute-force cone bakers: simple, slow (O(N^2) per texel with an early stop) and conservative.
// They are the oracles the fast bakers are tested against and what the techniques use until a
// fast baker is wired in.

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

namespace px {

// Conservative for the bilinear surface (CONVENTIONS §4): for every texel b and every point q of
// the surface, |q - b| >= c(b) (h(q) - h_b). A far cell is bounded by the max of its corners at
// its nearest point; a cell with b as a corner by its steepest slope (the mean value theorem along
// the segment from b, which stays in the cell). Not yet post-processed or quantised.
ConeMap bakeConservativeConesBruteForce(const HeightField& field, WrapMode wrap);

// Relaxed cones (Bán et al. 2024, CONE_TYPE 4): only cells that fall away from the apex limit the
// cone, at their nearest corner. Not yet post-processed or quantised.
ConeMap bakeRelaxedConesBruteForce(const HeightField& field, WrapMode wrap);

// Replaces each cone by the minimum over its 3x3 neighbourhood (wrap or clamp), which makes the
// bilinearly interpolated cone anywhere in a cell no wider than any of its corners' cones.
void applyNeighbourhoodMinimum(ConeMap& cones, WrapMode wrap);

// Rounds each stored sqrt(ratio) down to `levels` steps (255 or 65535): never widens a cone.
void quantiseDown(ConeMap& cones, int levels);

} // namespace px

#pragma once
// Brute-force cone bakers: every cell of the bilinear surface, ring by ring around the apex until
// no farther cell can narrow the cone (O(N^4) at worst). They are the oracles the fast bakers are
// tested against and the baseline of the benchmarks. Each cell's bound is exact for the cells
// around the apex and, elsewhere, at most a relative 1e-3 below the exact minimum for conservative
// cones and 3e-2 for relaxed ones (PX_BAKE_ORACLE_TOLERANCE, PX_BAKE_RELAXED_TOLERANCE in
// shaders/bake/cells.glsl; never above it). Not post-processed or quantised.

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

namespace px {

// Conservative for the bilinear surface (docs/conventions.md §4): for every texel b and every point
// q of the surface, |q - b| >= c(b) (h(q) - h_b).
ConeMap bakeConservativeConesBruteForce(const HeightField& field, WrapMode wrap);

// Relaxed, safe for the bilinear surface: for every point q where the surface falls away from
// b (grad h . (q - b) < 0), |q - b| >= c(b) (h(q) - h_b). The fast relaxed baker equals it.
ConeMap bakeRelaxedConesBruteForce(const HeightField& field, WrapMode wrap);

} // namespace px

#pragma once
// Independent brute-force checks of cone maps, in double precision, written from the definitions
// (docs/conventions.md §4, docs/cone-maps.md) rather than from the bakers' code.

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

namespace px::test {

struct ConeCheck {
    long points = 0;        // surface points (or ray samples) examined
    long violations = 0;    // points inside the cone (or rays that left the solid)
    double worst = 0.0;     // largest height above the cone (or depth of a left solid)
    double minRatio = 1e30; // smallest |q - b| / (h(q) - h_b) met (tightness)
};

// Samples the bilinear surface on an n x n grid per cell (edges included) over every cell that
// could reach into texel b's cone of ratio c (whole periods around b with repeat), and counts the
// points with h(q) > h_b + |q - b| / c + 1e-9.
ConeCheck checkConservative(const HeightField& field, WrapMode wrap, int bx, int by, double c,
                            int n);

// The relaxed property: rays that start on b's column above the apex and stay inside its cone
// (ratio c) never leave the solid once inside it. Samples start heights, directions and slopes,
// and each ray densely; a ray counts if it is inside the solid by more than `depth` somewhere and
// then above it by more than `depth`.
ConeCheck checkRelaxed(const HeightField& field, WrapMode wrap, int bx, int by, double c,
                       double depth);

// The original relaxed cone pre-process (Policarpo & Oliveira, GPU Gems 3 ch. 18): for every
// texel d higher than b, a ray from height 1 above b through d's top, stepped `steps` times
// beyond d to the first point above the (point-sampled) surface. Repeat only.
ConeMap bakeRelaxedConesGpuGems(const HeightField& field, int steps);

} // namespace px::test

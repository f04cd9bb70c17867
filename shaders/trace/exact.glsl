// `exact`: the reference. Walks every cell the ray crosses and solves the ray/bilinear-patch
// quadratic in each: the first root is the hit (docs/conventions.md §2).

float pxTraceExact(vec2 uv0, vec2 P) {
    vec2 X0 = pxCellCoords(uv0);
    vec2 dXY = pxCellsPerT(P);
    vec2 r = pxWalkCells(X0, dXY, pxStartT(), 1.0f, pxMaxSteps);
    if (r.x >= 0.0f)
        return r.x;
    // No root: either rounding at t = 1 (where f >= 0 always) or the cap ran out, leaving the
    // ray above the surface at r.y.
    return r.y >= 1.0f ? 1.0f : r.y;
}

// `cone`: conservative cone stepping. A sample found at or below the surface means the last step
// overshot (possible only where interpolated cones are wider than the true ones): the bracket is
// then walked cell by cell, exactly. If the step cap runs out the ray stops short (undershoot).

float pxTraceCone(vec2 uv0, vec2 P) {
    PxConeState s = pxConeMarch(uv0, P);
    if (s.hit >= 0.0f)
        return s.hit;
    if (!s.below || s.t <= s.tPrev)
        return s.t;
    vec2 X0 = pxCellCoords(uv0);
    vec2 dXY = vec2(P.x * float(pxMapSize.x), P.y * float(pxMapSize.y));
    vec2 r = pxWalkCells(X0, dXY, s.tPrev, s.t, pxMaxSteps);
    return r.x >= 0.0f ? r.x : s.t;
}

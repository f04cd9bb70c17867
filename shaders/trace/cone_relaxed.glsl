// `relaxed-cone`: relaxed cone stepping (Policarpo & Oliveira, GPU Gems 3 ch. 18). The cone sampled
// at the ray's position, interpolated between texels, may let the ray enter the solid once; the
// bracket the last step created holds that single crossing, and pxRefineSteps halvings find it. The
// step inside a cone is dt = c (z - h) / (c + |P|). Where that would not leave the current cell,
// the cell is solved exactly instead (docs/cone-maps.md §1, "a minimum step"): zero cones cannot
// stall the march and features smaller than a cell are not stepped over. (`cone` steps with its
// corners' cones instead: cone_conservative.glsl.)

struct PxConeState {
    float tPrev; // last position known above the surface
    float t;     // current position
    float hit;   // exact hit found by a cell solve, or -1
    bool below;  // the sample at t is at or below the surface
};

PxConeState pxConeMarch(vec2 uv0, vec2 P) {
    vec2 X0 = pxCellCoords(uv0);
    vec2 dXY = vec2(P.x * float(pxMapSize.x), P.y * float(pxMapSize.y));
    float lenP = length(P);
    PxConeState s;
    s.t = pxStartT();
    s.tPrev = s.t;
    s.hit = -1.0f;
    s.below = false;
    for (int i = 0; i < pxMaxSteps; ++i) {
        vec2 hc = pxConeSample(uv0 + P * s.t);
        float z = 1.0f - s.t;
        if (z <= hc.x) {
            s.below = true;
            return s;
        }
        float spread = hc.y + lenP; // 0 only for a zero cone seen straight down
        float coneStep = spread > 0.0f ? hc.y * (z - hc.x) / spread : 0.0f;
        ivec2 cell = pxCellAt(X0, dXY, s.t);
        float tCell = min(min(pxBorderT(cell.x, X0.x, dXY.x), pxBorderT(cell.y, X0.y, dXY.y)), 1.0f);
        s.tPrev = s.t;
        if (s.t + coneStep < tCell) {
            float root = pxSolveCell(cell, X0, dXY, s.t, tCell);
            if (root >= 0.0f) {
                s.hit = root;
                return s;
            }
            s.t = max(s.t, tCell);
        } else {
            s.t = min(s.t + coneStep, 1.0f);
        }
        if (s.t >= 1.0f) {
            s.below = true; // f(1) >= 0: the bottom is always solid
            return s;
        }
    }
    return s;
}

float pxTraceRelaxedCone(vec2 uv0, vec2 P) {
    PxConeState s = pxConeMarch(uv0, P);
    if (s.hit >= 0.0f)
        return s.hit;
    if (!s.below || s.t <= s.tPrev)
        return s.t;
    return pxBisect(uv0, P, s.tPrev, s.t);
}

// `relaxed-cone`: relaxed cone stepping (Policarpo & Oliveira, GPU Gems 3 ch. 18). The cone sampled
// at the ray's position, interpolated between texels, may let the ray enter the solid. The step
// inside a cone is dt = c (z - h) / (c + |P|). Where that would not leave the current cell, the
// cell is solved exactly instead (docs/cone-maps.md §1, "a minimum step"): zero cones cannot stall
// the march and features smaller than a cell are not stepped over. (`cone` steps with its corners'
// cones instead: cone_conservative.glsl.)
//
// The last step's bracket [tPrev, t] is not refined by halvings: the step may cross several
// features (a thin wall, then the floor behind it), and halvings keep any crossing, not the
// first. The bracket's cells are solved exactly instead, and a march whose cap runs out is
// finished by the cell walk. What remains is a step that passes through a feature and out again
// before its end (a needle at a grazing view): relaxed cones promise one crossing only for rays
// through their apex, and the interpolated cone is no cone of the surface.

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
    vec2 X0 = pxCellCoords(uv0);
    vec2 dXY = vec2(P.x * float(pxMapSize.x), P.y * float(pxMapSize.y));
    if (!s.below)
        return pxFinishExact(X0, dXY, s.t); // the cap ran out above the surface
    if (s.t <= s.tPrev)
        return s.t;
    vec2 r = pxWalkCells(X0, dXY, s.tPrev, s.t, PX_WALK_LIMIT);
    return r.x >= 0.0f ? r.x : s.t; // no root: rounding at the sample that found the solid
}

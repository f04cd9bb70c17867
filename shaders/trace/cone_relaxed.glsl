// `relaxed-cone`: relaxed cone stepping, then pxRefineSteps halvings of the bracket the last step
// created; the relaxed cone guarantees it holds a single crossing.

float pxTraceRelaxedCone(vec2 uv0, vec2 P) {
    PxConeState s = pxConeMarch(uv0, P);
    if (s.hit >= 0.0f)
        return s.hit;
    if (!s.below || s.t <= s.tPrev)
        return s.t;
    return pxBisect(uv0, P, s.tPrev, s.t);
}

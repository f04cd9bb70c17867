// `relaxed-cone`: relaxed cone stepping, then pxRefineSteps halvings of the bracket the last step
// created; the relaxed cone guarantees it holds a single crossing.

float pxTraceRelaxedCone(vec2 uv0, vec2 P) {
    PxConeState s = pxConeMarch(uv0, P);
    if (s.hit >= 0.0f)
        return s.hit;
    if (!s.below || s.t <= s.tPrev)
        return s.t;
    float lo = s.tPrev;
    float hi = s.t;
    for (int i = 0; i < pxRefineSteps; ++i) {
        float mid = 0.5f * (lo + hi);
        if (pxDepthGap(uv0, P, mid) >= 0.0f)
            hi = mid;
        else
            lo = mid;
    }
    return 0.5f * (lo + hi);
}

// `secant`: the linear search, then pxRefineSteps secant (regula falsi) steps on the bracket
// (Risser, Shah, Pattanaik 2007); the answer is the last secant's root, at no extra fetch.

float pxTraceSecant(vec2 uv0, vec2 P) {
    PxBracket b = pxLinearSearch(uv0, P);
    if (b.t0 == b.t1)
        return b.t1;
    for (int i = 0; i < pxRefineSteps; ++i) {
        float t = pxLinearRoot(b.t0, b.t1, b.f0, b.f1);
        float f = pxDepthGap(uv0, P, t);
        if (f >= 0.0f) {
            b.t1 = t;
            b.f1 = f;
        } else {
            b.t0 = t;
            b.f0 = f;
        }
    }
    return pxLinearRoot(b.t0, b.t1, b.f0, b.f1);
}

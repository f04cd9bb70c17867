// `relief`: relief mapping (Policarpo, Oliveira, Comba 2005): the linear search, then
// pxRefineSteps halvings of the bracket; the answer is the final bracket's midpoint.

float pxTraceRelief(vec2 uv0, vec2 P) {
    PxBracket b = pxLinearSearch(uv0, P);
    if (b.t0 == b.t1)
        return b.t1;
    float lo = b.t0;
    float hi = b.t1;
    for (int i = 0; i < pxRefineSteps; ++i) {
        float mid = 0.5f * (lo + hi);
        if (pxDepthGap(uv0, P, mid) >= 0.0f)
            hi = mid;
        else
            lo = mid;
    }
    return 0.5f * (lo + hi);
}

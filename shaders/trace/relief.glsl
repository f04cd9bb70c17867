// `relief`: relief mapping (Policarpo, Oliveira, Comba 2005): the linear search, then
// pxRefineSteps halvings of the bracket; the answer is the final bracket's midpoint.

float pxTraceRelief(vec2 uv0, vec2 P) {
    PxBracket b = pxLinearSearch(uv0, P);
    if (b.t0 == b.t1)
        return b.t1;
    return pxBisect(uv0, P, b.t0, b.t1);
}

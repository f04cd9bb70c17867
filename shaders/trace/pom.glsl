// `pom`: parallax occlusion mapping (Tatarchuk 2006): the linear search, then the crossing of
// the straight line between the two bracketing layers. Reuses the samples: no extra fetch.

float pxTracePom(vec2 uv0, vec2 P) {
    PxBracket b = pxLinearSearch(uv0, P);
    return pxLinearRoot(b.t0, b.t1, b.f0, b.f1);
}

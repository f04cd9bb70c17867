// `offset`: parallax mapping with offset limiting (Kaneko 2001, Welsh 2004). One fetch; the
// offset is the depth at uv0 times the view vector's xy, never divided by its z, so it stays
// bounded at grazing angles: |offset| <= s (1 - h).

float pxTraceOffset(vec2 uv0, vec2 P) {
    float h0 = pxHeight(uv0);
    return (1.0f - h0) * pxCosTheta(P);
}

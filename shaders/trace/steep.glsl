// `steep`: steep parallax mapping (McGuire & McGuire 2005): the first layer below the surface.

float pxTraceSteep(vec2 uv0, vec2 P) {
    return pxLinearSearch(uv0, P).t1;
}

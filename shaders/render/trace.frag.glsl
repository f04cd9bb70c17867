// The canonical trace scene on the GPU (docs/conventions.md §5): pixel (i, j) of the R x R RGBA32F
// target is ray (i, j). Its uv0 comes from pxRayOrigins (the CPU's float values, reduced to the
// tile as Tracer::trace does), its direction P from pxRayP (bounded as on the CPU). Writes (u, v,
// t, fetches), u and v not wrapped relative to the tile the ray entered.

layout(location = 0) out vec4 pxTraceOut;

void main() {
    ivec2 ray = ivec2(gl_FragCoord.xy);
    vec2 uv0 = texelFetch(pxRayOrigins, ray, 0).rg;
#if defined(PX_HAS_PARALLAX)
    pxUseHeightLevel(0);
    vec2 P = pxBoundParallax(pxRayP); // as Tracer::trace bounds it
    float t = pxTraceRay(uv0, P);
    pxTraceOut = vec4(uv0 + P * t, t, float(pxFetches));
#else
    pxTraceOut = vec4(uv0, 0.0, 0.0);
#endif
}

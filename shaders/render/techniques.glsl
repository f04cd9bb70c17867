// The variant's technique: one of the shared kernels, chosen when the shader is generated.

float pxTraceTechnique(vec2 uv0, vec2 P) {
#if defined(PX_TECHNIQUE_OFFSET)
    return pxTraceOffset(uv0, P);
#elif defined(PX_TECHNIQUE_STEEP)
    return pxTraceSteep(uv0, P);
#elif defined(PX_TECHNIQUE_POM)
    return pxTracePom(uv0, P);
#elif defined(PX_TECHNIQUE_RELIEF)
    return pxTraceRelief(uv0, P);
#elif defined(PX_TECHNIQUE_SECANT)
    return pxTraceSecant(uv0, P);
#elif defined(PX_TECHNIQUE_CONE)
    return pxTraceCone(uv0, P);
#elif defined(PX_TECHNIQUE_RELAXED_CONE)
    return pxTraceRelaxedCone(uv0, P);
#elif defined(PX_TECHNIQUE_PYRAMID)
    return pxTracePyramid(uv0, P);
#elif defined(PX_TECHNIQUE_EXACT)
    return pxTraceExact(uv0, P);
#else
    return 0.0f;
#endif
}

// As Tracer::trace: looking straight down, or with s = 0, every technique is one fetch.
float pxTraceRay(vec2 uv0, vec2 P) {
    if ((P.x == 0.0f && P.y == 0.0f) || pxScale == 0.0f)
        return pxTraceStraightDown(uv0);
    float t = pxTraceTechnique(uv0, P);
    // The kernels keep t in [0, 1]; this only guards against NaN heights reaching them.
    if (!(t >= 0.0f))
        t = 0.0f;
    return min(t, 1.0f);
}

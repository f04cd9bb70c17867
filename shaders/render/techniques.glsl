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

// As Tracer::trace, through the same rules (trace/common.glsl).
float pxTraceRay(vec2 uv0, vec2 P) {
    if (pxLooksStraightDown(P))
        return pxTraceStraightDown(uv0);
    return pxKeepT(pxTraceTechnique(uv0, P));
}

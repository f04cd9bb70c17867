#pragma once
// The canonical trace scene (docs/conventions.md §5) on the GPU: one fragment per ray into an R x R
// RGBA32F target holding (u, v, t, fetches), the same kernels as the CPU Tracer (shaders/trace/).
// Heights go up as R32F and cone maps as RG32F, the CPU's floats unchanged, so both sides read the
// same values: `parallax-cli trace --gpu` and the tests that hold GPU == CPU.

#include "parallax/render/ShaderCache.h"
#include "parallax/trace/TraceScene.h"
#include "parallax/trace/Tracer.h"

#include <vector>

namespace px {

struct GpuTraceTiming {
    double milliseconds = 0.0; // the trace pass alone, the fastest of the timed draws
    bool gpuTimer = false;     // measured with a GL timer query (real GPUs) or a steady clock
    std::string renderer;      // GL_RENDERER of the context that traced
};

// Traces every ray of `scene`. The derived maps the technique reads are taken from `maps` when
// given, else baked (the same bakers the CPU Tracer uses). Errors: the Tracer's (empty height map,
// parameters out of range), the scene's, and GL limits (R larger than the GL renders).
// Needs a current OpenGL 4.3 context.
// `kernels` picks the flavour: Verify matches the CPU to the bit, Production filters in hardware
// (its fetches count each hardware sample or gather as one, as the CPU counts its reads).
Result<std::vector<TraceResult>> traceSceneGpu(ShaderCache& shaders, const TraceMaps& maps,
                                               Technique technique, const TraceParams& params,
                                               float heightScale, const TraceScene& scene,
                                               GpuTraceTiming* timing = nullptr,
                                               KernelFlavour kernels = KernelFlavour::Verify);

// The trace pass of traceSceneGpu drawn `frames` times after one untimed warm-up, the fastest
// reported, without reading the hits back: what a bench times per setting. The set-up (ray
// origins, uploads, the target) is done once, so a 1440 x 1440 sweep costs one set-up a setting.
Result<GpuTraceTiming> timeSceneGpu(ShaderCache& shaders, const TraceMaps& maps,
                                    Technique technique, const TraceParams& params,
                                    float heightScale, const TraceScene& scene, int frames,
                                    KernelFlavour kernels = KernelFlavour::Verify);

} // namespace px

namespace px {

// traceSceneGpu on a headless context made for the call (HeadlessContext): for the command line.
Result<std::vector<TraceResult>> traceSceneHeadless(const TraceMaps& maps, Technique technique,
                                                    const TraceParams& params, float heightScale,
                                                    const TraceScene& scene,
                                                    GpuTraceTiming* timing = nullptr,
                                                    KernelFlavour kernels = KernelFlavour::Verify);

} // namespace px

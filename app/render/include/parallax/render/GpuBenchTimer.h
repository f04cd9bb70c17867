#pragma once
// The bench's GPU timer (parallax/eval/Bench.h, GpuFrameTimer) on an OpenGL context of the caller's
// choosing: the canonical scene traced by the GPU kernels in the flavour asked for, timed (one
// untimed warm-up for compiles and JIT, then the fastest of `frames`), then the bench's own R x R
// rays traced again, untimed, so the bench measures the GPU kernels' error too. `parallax-cli
// bench --gpu` times on a headless EGL context; the editor's Compare panel on a context shared
// with its viewports' (app/studio/jobs/EditorGlContext.h), so both time the GPU that draws.
//
// A frame is the request's width x height rays (1440^2 = 1920 x 1080); `rays` > 0 times an
// R x R trace instead and scales its time to the frame's rays (the label says so): software
// renderers spend seconds on a full frame.

#include "parallax/eval/Bench.h"
#include "parallax/render/ShaderCache.h"

#include <functional>
#include <memory>
#include <string>

namespace px {

struct GpuBenchOptions {
    int frames = 1;
    int rays = 0;         // R of the timed trace; 0: the request's frame
    int softwareRays = 0; // R on a software renderer (llvmpipe); 0: as `rays`
    KernelFlavour kernels = KernelFlavour::Production;
};

// An OpenGL 4.3 context made current on the calling thread; `keepAlive` holds it (and releases it
// on that thread when the timer ends). `name` says which context it is, for the label.
struct BenchContext {
    std::shared_ptr<void> keepAlive;
    std::string name;
};
using BenchContextFactory = std::function<Result<BenchContext>()>;

// A headless EGL context (HeadlessContext.h), named by its platform.
Result<BenchContext> headlessBenchContext();

class GpuBenchTimer {
public:
    // Calls `makeContext` on the calling thread; the timer must be used on that thread only.
    // Fails with "no GPU timing: " and the factory's sentence.
    static Result<std::unique_ptr<GpuBenchTimer>> create(const GpuBenchOptions& options,
                                                         const BenchContextFactory& makeContext);
    ~GpuBenchTimer();
    GpuBenchTimer(const GpuBenchTimer&) = delete;
    GpuBenchTimer& operator=(const GpuBenchTimer&) = delete;

    Result<GpuFrameTiming> time(const GpuFrameRequest& request);

private:
    GpuBenchTimer() = default;
    BenchContext m_context; // declared first: the shaders are deleted while it is still current
    ShaderCache m_shaders;
    GpuBenchOptions m_options;
    std::string m_label;
};

// A GpuFrameTimer that makes its GpuBenchTimer on first use, on the thread the bench runs on (a
// worker thread in the editor), and reports a context that could not be made as each request's
// error.
GpuFrameTimer lazyGpuBenchTimer(const GpuBenchOptions& options, BenchContextFactory makeContext);

} // namespace px

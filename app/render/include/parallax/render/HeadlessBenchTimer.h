#pragma once
// The bench's GPU timer (parallax/eval/Bench.h, GpuFrameTimer) on a headless OpenGL context: the
// canonical scene traced by the GPU kernels in the flavour asked for, timed (one untimed warm-up
// for compiles and JIT, then the fastest of `frames`), then the bench's own R x R rays traced
// again, untimed, so the bench measures the GPU kernels' error too. `parallax-cli bench --gpu` and
// the editor's Compare panel use it.
//
// A frame is the request's width x height rays (1440^2 = 1920 x 1080); `rays` > 0 times an
// R x R trace instead and scales its time to the frame's rays (the label says so): software
// renderers spend seconds on a full frame.

#include "parallax/eval/Bench.h"
#include "parallax/render/ShaderCache.h"

#include <memory>

namespace px {

class HeadlessContext;

struct HeadlessBenchOptions {
    int frames = 1;
    int rays = 0;         // R of the timed trace; 0: the request's frame
    int softwareRays = 0; // R on a software renderer (llvmpipe); 0: as `rays`
    KernelFlavour kernels = KernelFlavour::Production;
};

class HeadlessBenchTimer {
public:
    // Makes a context current on the calling thread; the timer must be used on that thread only.
    // Fails with "no GPU timing: " and HeadlessContext's sentence.
    static Result<std::unique_ptr<HeadlessBenchTimer>> create(const HeadlessBenchOptions& options);
    ~HeadlessBenchTimer();

    Result<GpuFrameTiming> time(const GpuFrameRequest& request);

private:
    HeadlessBenchTimer() = default;
    std::unique_ptr<HeadlessContext> m_context;
    ShaderCache m_shaders;
    HeadlessBenchOptions m_options;
    std::string m_label;
};

// A GpuFrameTimer that makes its HeadlessBenchTimer on first use, on the thread the bench runs on
// (a worker thread in the editor), and reports a missing context as each request's error.
GpuFrameTimer lazyHeadlessBenchTimer(const HeadlessBenchOptions& options);

} // namespace px

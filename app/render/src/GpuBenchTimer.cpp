#include "parallax/render/GpuBenchTimer.h"

#include "parallax/render/GpuTracer.h"
#include "parallax/render/HeadlessContext.h"

#include <cmath>
#include <cstdio>
#include <optional>

namespace px {

Result<BenchContext> headlessBenchContext() {
    Result<std::unique_ptr<HeadlessContext>> context = HeadlessContext::create();
    if (!context)
        return context.error();
    std::shared_ptr<HeadlessContext> held(std::move(*context));
    return BenchContext{held, "headless " + held->platform()};
}

Result<std::unique_ptr<GpuBenchTimer>>
GpuBenchTimer::create(const GpuBenchOptions& options, const BenchContextFactory& makeContext) {
    Result<BenchContext> context = makeContext();
    if (!context)
        return Error{"no GPU timing: " + context.error().message};
    std::unique_ptr<GpuBenchTimer> timer(new GpuBenchTimer);
    timer->m_context = std::move(*context);
    timer->m_options = options;
    const GlInfo gl = currentGlInfo();
    if (Status ok = requireGl43(gl); !ok)
        return Error{"no GPU timing: " + ok.error().message};
    timer->m_label = gl.renderer + (gl.software() ? " [software rasteriser: CPU time]" : "") +
                     ", " + timer->m_context.name;
    if (gl.software() && options.softwareRays > 0)
        timer->m_options.rays = options.softwareRays;
    return timer;
}

GpuBenchTimer::~GpuBenchTimer() = default;

Result<GpuFrameTiming> GpuBenchTimer::time(const GpuFrameRequest& r) {
    const double frameRays = double(r.width) * r.height;
    TraceScene scene;
    scene.rays =
        m_options.rays > 0 ? m_options.rays : static_cast<int>(std::lround(std::sqrt(frameRays)));
    scene.polarDeg = r.polarDeg;
    scene.azimuthDeg = r.azimuthDeg;
    const Technique technique = r.setting->technique;
    const TraceParams& params = r.setting->params;
    // One set-up, one warm-up draw, then the timed draws: the fastest is the setting's time.
    Result<GpuTraceTiming> timing = timeSceneGpu(m_shaders, r.maps, technique, params, r.scale,
                                                 scene, m_options.frames, m_options.kernels);
    if (!timing)
        return Error{"no GPU timing: " + timing.error().message};
    const double best = timing->milliseconds;
    const bool timerQuery = timing->gpuTimer;
    const double traced = double(scene.rays) * scene.rays;
    std::string label =
        m_label + (timerQuery ? ", GL timer query" : ", steady clock around glFinish");
    if (traced != frameRays) {
        char note[96];
        std::snprintf(note, sizeof note, ", scaled from %d x %d rays", scene.rays, scene.rays);
        label += note;
    }
    GpuFrameTiming result{best * frameRays / traced,
                          label,
                          std::string(shader::kernelFlavourName(m_options.kernels)),
                          {}};
    if (r.rays > 0) {
        scene.rays = r.rays;
        Result<std::vector<TraceResult>> hits = traceSceneGpu(
            m_shaders, r.maps, technique, params, r.scale, scene, nullptr, m_options.kernels);
        if (!hits)
            return Error{"no GPU hits: " + hits.error().message};
        result.hits = std::move(*hits);
    }
    return result;
}

GpuFrameTimer lazyGpuBenchTimer(const GpuBenchOptions& options, BenchContextFactory makeContext) {
    struct Lazy {
        GpuBenchOptions options;
        BenchContextFactory makeContext;
        std::unique_ptr<GpuBenchTimer> timer;
        std::optional<Error> failed;
    };
    auto lazy = std::make_shared<Lazy>();
    lazy->options = options;
    lazy->makeContext = std::move(makeContext);
    return [lazy](const GpuFrameRequest& r) -> Result<GpuFrameTiming> {
        if (!lazy->timer && !lazy->failed) {
            Result<std::unique_ptr<GpuBenchTimer>> made =
                GpuBenchTimer::create(lazy->options, lazy->makeContext);
            if (made)
                lazy->timer = std::move(*made);
            else
                lazy->failed = made.error();
        }
        if (lazy->failed)
            return *lazy->failed;
        return lazy->timer->time(r);
    };
}

} // namespace px

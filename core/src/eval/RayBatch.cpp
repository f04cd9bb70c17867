#include "RayBatch.h"

#include <atomic>
#include <chrono>
#include <tbb/parallel_for.h>

namespace px {

std::optional<double> traceBatch(const Tracer& tracer, const TraceScene& scene, RayTiming timing,
                                 std::vector<TraceResult>& hits, const std::atomic<bool>* cancel) {
    auto stopRequested = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
    const int R = scene.rays;
    const glm::vec2 P = parallaxVector(tracer.heightScale(), scene.polarDeg, scene.azimuthDeg);
    hits.assign(static_cast<std::size_t>(R) * R, TraceResult{});
    auto traceRow = [&](int j) {
        TraceResult* row = hits.data() + static_cast<std::size_t>(j) * R;
        for (int i = 0; i < R; ++i)
            row[i] = tracer.trace(rayOrigin(scene, i, j), P);
    };

    if (timing == RayTiming::Parallel) {
        std::atomic<bool> cancelled{false};
        tbb::parallel_for(0, R, [&](int j) {
            if (cancelled.load(std::memory_order_relaxed) || stopRequested()) {
                cancelled.store(true, std::memory_order_relaxed);
                return;
            }
            traceRow(j);
        });
        if (cancelled.load())
            return std::nullopt;
        return 0.0;
    }

    using Clock = std::chrono::steady_clock;
    Clock::duration elapsed{};
    for (int j = 0; j < R; ++j) {
        if (stopRequested())
            return std::nullopt;
        const Clock::time_point start = Clock::now();
        traceRow(j);
        elapsed += Clock::now() - start;
    }
    return std::chrono::duration<double, std::nano>(elapsed).count();
}

} // namespace px

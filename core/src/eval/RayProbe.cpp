#include "RayProbe.h"

#include "parallax/eval/HitErrorStats.h"
#include "parallax/eval/QuantileBound.h"
#include "parallax/trace/TraceScene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <tbb/parallel_for.h>

namespace px {
namespace {

// splitmix64: a fixed, portable generator (std's distributions differ between libraries).
struct SplitMix {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

bool isValidHit(const TraceResult& r) {
    return std::isfinite(r.u) && std::isfinite(r.v) && std::isfinite(r.t) && r.t >= 0.0f &&
           r.t <= 1.0f;
}

} // namespace

RaySample sampleRays(int raysPerSide, double polarDeg, std::span<const double> azimuthDeg,
                     float scale, RayModel model) {
    RaySample rays;
    rays.polarDeg = polarDeg;
    const std::size_t perAzimuth = static_cast<std::size_t>(raysPerSide) * raysPerSide;
    rays.uv0.reserve(perAzimuth * azimuthDeg.size());
    rays.P.reserve(perAzimuth * azimuthDeg.size());
    const double n = raysPerSide;
    for (std::size_t a = 0; a < azimuthDeg.size(); ++a) {
        glm::vec2 P = parallaxVector(scale, polarDeg, azimuthDeg[a]);
        if (model == RayModel::NormalisedView)
            P *= static_cast<float>(std::cos(polarDeg * std::numbers::pi / 180.0));
        // One stream per azimuth and angle, independent of the settings measured on it.
        SplitMix rng{0x5EEDULL + 7919ULL * a + static_cast<std::uint64_t>(polarDeg * 1000.0)};
        for (int j = 0; j < raysPerSide; ++j) {
            for (int i = 0; i < raysPerSide; ++i) {
                const double u = (i + rng.uniform()) / n;
                const double v = (j + rng.uniform()) / n;
                rays.uv0.emplace_back(u, v);
                rays.P.push_back(P);
            }
        }
    }
    return rays;
}

RangeTrace tracerRange(const Tracer& tracer) {
    return [&tracer](const RaySample& rays, std::size_t begin, std::size_t end,
                     std::span<TraceResult> hits) {
        for (std::size_t k = begin; k < end; ++k)
            hits[k] = tracer.trace(rays.uv0[k], rays.P[k]);
    };
}

std::optional<std::vector<TraceResult>> traceSample(const RaySample& rays, const RangeTrace& trace,
                                                    const std::atomic<bool>* cancel) {
    double fetches = 0.0;
    return traceSampleWithin(rays, trace, cancel, std::numeric_limits<double>::infinity(), fetches);
}

std::optional<std::vector<TraceResult>>
traceSampleWithin(const RaySample& rays, const RangeTrace& trace, const std::atomic<bool>* cancel,
                  double maxMeanFetches, double& fetchesAtLeast) {
    std::vector<TraceResult> hits(rays.uv0.size());
    constexpr std::size_t kBlock = 256;
    const std::size_t blocks = (hits.size() + kBlock - 1) / kBlock;
    // Fetches are whole numbers: their running sum is exact, so "over the limit" is the same
    // verdict whichever blocks have run.
    const double limit = maxMeanFetches * static_cast<double>(hits.size());
    std::atomic<std::int64_t> fetches{0};
    std::atomic<bool> stopped{false}, over{false};
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        if (stopped.load(std::memory_order_relaxed) ||
            (cancel && cancel->load(std::memory_order_relaxed))) {
            stopped.store(true, std::memory_order_relaxed);
            return;
        }
        const std::size_t begin = b * kBlock, end = std::min(hits.size(), (b + 1) * kBlock);
        trace(rays, begin, end, hits);
        std::int64_t sum = 0;
        for (std::size_t k = begin; k < end; ++k)
            sum += hits[k].fetches;
        if (static_cast<double>(fetches.fetch_add(sum, std::memory_order_relaxed) + sum) > limit) {
            over.store(true, std::memory_order_relaxed);
            stopped.store(true, std::memory_order_relaxed);
        }
    });
    fetchesAtLeast = static_cast<double>(fetches.load()) / static_cast<double>(hits.size());
    if (over.load()) // over the limit even where dividing by the ray count rounds down to it
        fetchesAtLeast = std::max(fetchesAtLeast, std::nextafter(maxMeanFetches, INFINITY));
    if (stopped.load())
        return std::nullopt;
    return hits;
}

double timeSample(const RaySample& rays, const RangeTrace& trace) {
    std::vector<TraceResult> hits(rays.uv0.size());
    using Clock = std::chrono::steady_clock;
    double best = std::numeric_limits<double>::infinity();
    for (int pass = 0; pass < 2; ++pass) {
        const Clock::time_point start = Clock::now();
        trace(rays, 0, hits.size(), hits);
        best =
            std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - start).count());
    }
    return hits.empty() ? 0.0 : best / static_cast<double>(hits.size());
}

AngleMeasure measureAngle(const RaySample& rays, std::span<const TraceResult> hits,
                          std::span<const TraceResult> reference, int width, int height,
                          double confidence) {
    AngleMeasure m;
    m.polarDeg = rays.polarDeg;
    m.rays = static_cast<std::int64_t>(hits.size());
    // An invalid hit counts as infinitely wrong: it cannot pass any budget.
    std::vector<double> errors(hits.size());
    double fetches = 0.0;
    for (std::size_t k = 0; k < hits.size(); ++k) {
        errors[k] = isValidHit(hits[k]) ? hitErrorTexels(hits[k], reference[k], width, height)
                                        : std::numeric_limits<double>::infinity();
        fetches += hits[k].fetches;
    }
    m.meanFetches = hits.empty() ? 0.0 : fetches / static_cast<double>(hits.size());
    for (double e : errors) {
        m.maxError = std::max(m.maxError, e);
        m.wrongSurface += e > kWrongSurfaceTexels ? 1 : 0;
    }
    const std::int64_t rank = quantileUpperRank(m.rays, 0.99, confidence);
    std::vector<double> sorted = errors;
    std::sort(sorted.begin(), sorted.end());
    if (!sorted.empty()) {
        m.p99 = sorted[static_cast<std::size_t>(
                           std::max(1.0, std::ceil(0.99 * static_cast<double>(m.rays)))) -
                       1];
        m.p99Bound = rank > 0 ? sorted[static_cast<std::size_t>(rank - 1)]
                              : std::numeric_limits<double>::infinity();
    }
    return m;
}

bool meetsBudget(const AngleMeasure& m, const ErrorBudget& budget) {
    switch (budget.metric) {
    case BudgetMetric::P99:
        return m.p99Bound <= budget.texels;
    case BudgetMetric::Max:
        return m.maxError <= budget.texels;
    case BudgetMetric::NoWrongSurface:
        return m.p99Bound <= budget.texels && m.wrongSurface == 0;
    }
    return false;
}

} // namespace px

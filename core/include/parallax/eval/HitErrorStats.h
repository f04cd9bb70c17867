#pragma once
// Accuracy and cost of a technique's hits against the exact reference's hits for the same rays
// (docs/conventions.md §5: error in texels of the map, cost in fetches). Pure functions of the
// hits: the same rays give the same figures on every run and thread count.

#include "parallax/trace/Tracer.h"

#include <cstdint>
#include <span>
#include <vector>

namespace px {

// A hit further than this from the exact one has found another surface, not a nearby point of
// the same one (the "wrong surface" count of the bench).
inline constexpr double kWrongSurfaceTexels = 2.0;

// A technique documented exact (`cone`, `pyramid`, `exact`) keeps every ray within this of the
// reference: a bench or stability row where one ray is further fails.
inline constexpr double kExactTexels = 0.05;
bool isDocumentedExact(Technique technique);

struct HitErrorStats {
    std::int64_t rays = 0;
    std::int64_t invalid = 0;      // non-finite u, v or t, or t outside [0, 1]: no error taken
    std::int64_t wrongSurface = 0; // valid rays with error > kWrongSurfaceTexels
    double meanError = 0.0;        // texels, over valid rays
    double p99Error = 0.0;         // nearest-rank 99th percentile, texels
    double maxError = 0.0;         // over valid rays: every ray, not a percentile
    double meanFetches = 0.0;      // over all rays
    double p99Fetches = 0.0;       // nearest-rank 99th percentile
    int maxFetches = 0;
};

// Accumulates the rays of one or several traces (maps, scales) of one technique and setting, so
// pooled percentiles are true percentiles of every ray rather than averages of percentiles.
class HitErrorAccumulator {
public:
    // `hits` and `reference` are the same rays in the same order; W x H is the map's size.
    void add(std::span<const TraceResult> hits, std::span<const TraceResult> reference, int width,
             int height);
    // One ray whose error is already measured, in texels (the editor compares rendered hits).
    void addError(double errorTexels, int fetches);
    HitErrorStats stats() const;

private:
    std::vector<double> m_errors; // valid rays only
    std::vector<int> m_fetches;
    std::int64_t m_invalid = 0;
};

HitErrorStats measureHits(std::span<const TraceResult> hits, std::span<const TraceResult> reference,
                          int width, int height);

// Nearest-rank percentile (q in (0, 1]) of unsorted values: the smallest value with at least
// q of them at or below it; 0 for none. Reorders `values`.
double nearestRankPercentile(std::vector<double>& values, double q);

} // namespace px

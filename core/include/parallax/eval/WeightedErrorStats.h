#pragma once
// Error statistics where each sample stands for a share of the texture's area: the editor's
// pixels, of which a near one covers less of the material than a far one. The bench's rays enter
// on an even grid over the tile, each standing for the same area; weighting a view's pixels by
// the area they cover makes its figures the bench's kind, and independent of how many pixels the
// window gives each part of the surface. With equal weights the figures are exactly
// HitErrorAccumulator's (nearest rank), so the two agree wherever they see the same rays.

#include <cstdint>
#include <utility>
#include <vector>

namespace px {

struct WeightedErrorStats {
    std::int64_t samples = 0;
    double weight = 0.0;            // the weights' sum (an area, in the caller's unit)
    double meanError = 0.0;         // weighted mean, texels
    double p99Error = 0.0;          // weighted nearest rank: the least error covering 99 %
    double maxError = 0.0;          // every sample
    double wrongSurfaceShare = 0.0; // weight of errors over kWrongSurfaceTexels, over the sum
};

class WeightedErrorAccumulator {
public:
    // A non-finite error or a weight that is not finite and positive is left out.
    void add(double errorTexels, double weight);
    WeightedErrorStats stats() const;

private:
    std::vector<std::pair<double, double>> m_samples; // (error, weight)
};

// The smallest value whose weight, with that of every smaller value, reaches q (in (0, 1]) of the
// sum; 0 for none. With equal weights: nearestRankPercentile. Reorders `samples`.
double weightedNearestRank(std::vector<std::pair<double, double>>& samples, double q);

} // namespace px

#include "parallax/eval/WeightedErrorStats.h"

#include "parallax/eval/HitErrorStats.h"

#include <algorithm>
#include <cmath>

namespace px {

void WeightedErrorAccumulator::add(double errorTexels, double weight) {
    if (std::isfinite(errorTexels) && std::isfinite(weight) && weight > 0.0)
        m_samples.emplace_back(errorTexels, weight);
}

double weightedNearestRank(std::vector<std::pair<double, double>>& samples, double q) {
    if (samples.empty())
        return 0.0;
    std::sort(samples.begin(), samples.end());
    double total = 0.0;
    for (const auto& s : samples)
        total += s.second;
    // Summed in the same order as compared, so equal weights reach q * n at rank ceil(q * n).
    const double target = q * total;
    double covered = 0.0;
    for (const auto& [value, weight] : samples) {
        covered += weight;
        if (covered >= target)
            return value;
    }
    return samples.back().first; // rounding left the sum a hair short of the target
}

WeightedErrorStats WeightedErrorAccumulator::stats() const {
    WeightedErrorStats s;
    s.samples = static_cast<std::int64_t>(m_samples.size());
    if (m_samples.empty())
        return s;
    double weighted = 0.0, wrong = 0.0;
    for (const auto& [error, weight] : m_samples) {
        s.weight += weight;
        weighted += error * weight;
        wrong += error > kWrongSurfaceTexels ? weight : 0.0;
        s.maxError = std::max(s.maxError, error);
    }
    s.meanError = weighted / s.weight;
    s.wrongSurfaceShare = wrong / s.weight;
    std::vector<std::pair<double, double>> samples = m_samples;
    s.p99Error = weightedNearestRank(samples, 0.99);
    return s;
}

} // namespace px

#include "parallax/eval/HitErrorStats.h"

#include "parallax/trace/TraceScene.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace px {
namespace {

bool isValid(const TraceResult& r) {
    return std::isfinite(r.u) && std::isfinite(r.v) && std::isfinite(r.t) && r.t >= 0.0f &&
           r.t <= 1.0f;
}

} // namespace

bool isDocumentedExact(Technique technique) {
    return technique == Technique::Cone || technique == Technique::RelaxedCone ||
           technique == Technique::Pyramid || technique == Technique::Exact;
}

double nearestRankPercentile(std::vector<double>& values, double q) {
    if (values.empty())
        return 0.0;
    const auto n = static_cast<double>(values.size());
    const auto rank = static_cast<std::size_t>(std::max(1.0, std::ceil(q * n))) - 1;
    const auto nth =
        values.begin() + static_cast<std::ptrdiff_t>(std::min(rank, values.size() - 1));
    std::nth_element(values.begin(), nth, values.end());
    return *nth;
}

void HitErrorAccumulator::add(std::span<const TraceResult> hits,
                              std::span<const TraceResult> reference, int width, int height) {
    assert(hits.size() == reference.size());
    m_errors.reserve(m_errors.size() + hits.size());
    m_fetches.reserve(m_fetches.size() + hits.size());
    for (std::size_t k = 0; k < hits.size(); ++k) {
        m_fetches.push_back(hits[k].fetches);
        if (!isValid(hits[k])) {
            ++m_invalid;
            continue;
        }
        m_errors.push_back(hitErrorTexels(hits[k], reference[k], width, height));
    }
}

void HitErrorAccumulator::addError(double errorTexels, int fetches) {
    m_fetches.push_back(fetches);
    if (std::isfinite(errorTexels))
        m_errors.push_back(errorTexels);
    else
        ++m_invalid;
}

HitErrorStats HitErrorAccumulator::stats() const {
    HitErrorStats s;
    s.rays = static_cast<std::int64_t>(m_fetches.size());
    s.invalid = m_invalid;
    if (!m_errors.empty()) {
        s.meanError = std::accumulate(m_errors.begin(), m_errors.end(), 0.0) /
                      static_cast<double>(m_errors.size());
        s.maxError = *std::max_element(m_errors.begin(), m_errors.end());
        s.wrongSurface = std::count_if(m_errors.begin(), m_errors.end(),
                                       [](double e) { return e > kWrongSurfaceTexels; });
        std::vector<double> errors = m_errors;
        s.p99Error = nearestRankPercentile(errors, 0.99);
    }
    if (!m_fetches.empty()) {
        std::vector<double> fetches(m_fetches.begin(), m_fetches.end());
        s.meanFetches =
            std::accumulate(fetches.begin(), fetches.end(), 0.0) / static_cast<double>(s.rays);
        s.maxFetches = *std::max_element(m_fetches.begin(), m_fetches.end());
        s.p99Fetches = nearestRankPercentile(fetches, 0.99);
    }
    return s;
}

HitErrorStats measureHits(std::span<const TraceResult> hits, std::span<const TraceResult> reference,
                          int width, int height) {
    HitErrorAccumulator acc;
    acc.add(hits, reference, width, height);
    return acc.stats();
}

} // namespace px

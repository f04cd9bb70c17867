#include "parallax/eval/QuantileBound.h"

#include <cmath>

namespace px {

std::int64_t quantileUpperRank(std::int64_t n, double q, double confidence) {
    if (n <= 0 || !(q > 0.0 && q < 1.0) || !(confidence > 0.0 && confidence < 1.0))
        return 0;
    // Binomial(n, q) pmf summed upwards in log space: n is up to ~10^5, where direct powers
    // underflow.
    const double lq = std::log(q);
    const double lp = std::log1p(-q);
    const auto N = static_cast<double>(n);
    double cdf = 0.0;
    for (std::int64_t j = 0; j < n; ++j) {
        const auto J = static_cast<double>(j);
        const double logPmf = std::lgamma(N + 1.0) - std::lgamma(J + 1.0) -
                              std::lgamma(N - J + 1.0) + J * lq + (N - J) * lp;
        cdf += std::exp(logPmf);
        if (cdf >= confidence)
            return j + 1; // P(Bin <= j) >= confidence: X(j + 1) bounds the quantile
    }
    return 0; // X(n) is not enough: P(Bin <= n - 1) = 1 - q^n < confidence
}

double zeroOfNUpperFraction(std::int64_t n, double confidence) {
    if (n <= 0)
        return 1.0;
    return 1.0 - std::pow(1.0 - confidence, 1.0 / static_cast<double>(n));
}

} // namespace px

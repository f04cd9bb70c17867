#pragma once
// Distribution-free confidence bounds from a sample of rays, for the recommendation: it measures
// a subsample of the rays and must say how far the whole can be from what it saw.

#include <cstdint>

namespace px {

// The 1-based rank k of the order statistic X(k) of n independent draws that bounds the q-quantile
// from above with probability `confidence`: P(quantile <= X(k)) >= confidence, i.e. the smallest k
// with P(Binomial(n, q) <= k - 1) >= confidence. 0 when n draws are too few for any k <= n.
std::int64_t quantileUpperRank(std::int64_t n, double q, double confidence);

// When none of n draws has a property, the fraction p of the whole that has it is below this with
// probability `confidence`: 1 - (1 - confidence)^(1/n) (about -ln(1 - confidence) / n).
double zeroOfNUpperFraction(std::int64_t n, double confidence);

} // namespace px

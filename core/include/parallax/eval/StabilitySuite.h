#pragma once
// The stability suite behind `parallax-cli stability`: named stiff and extreme cases (grazing
// views, degenerate scales and maps, far-tiled uv, broken inputs), each traced with every technique
// at its default setting. A row passes when every ray is finite with t in [0, 1], no ray makes
// more fetches than the technique's cap, and the error stays within the bound the technique
// documents for that case (the rules of boundRules(), applied in one place: StabilityCases.cpp).

#include "parallax/Result.h"
#include "parallax/eval/EvalControl.h"
#include "parallax/eval/HitErrorStats.h"
#include "parallax/trace/Technique.h"
#include "parallax/trace/Tracer.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace px {

enum class BoundKind {
    None,        // stability only: the technique promises no accuracy on this input
    MaxTexels,   // every ray within `limit` texels of the reference hit
    P99Texels,   // 99% of the rays within `limit` texels
    NoOvershoot, // no ray ends more than `limit` texels past the reference hit (conservative)
    MaxDepth,    // every ray's t within `limit` of the reference t (rays that do not move)
};

struct ErrorBound {
    BoundKind kind = BoundKind::None;
    double limit = 0.0;
    std::string rule; // the documented rule that set it, for people
};

struct StabilityCaseInfo {
    std::string_view name;        // as on the command line: "polar-89.9"
    std::string_view description; // what it exercises
};

// Every case, in the order the suite runs them.
std::span<const StabilityCaseInfo> stabilityCases();

// One line per technique: the accuracy it documents and where the promise is void.
struct BoundRule {
    Technique technique;
    std::string_view rule;
};
std::span<const BoundRule> boundRules();

struct StabilityRow {
    std::string caseName;
    std::string technique; // a technique's name, or "loader" for the input-rejection case
    bool passed = false;
    std::string figure;  // what was checked, with the measured value: "p99 0.31 <= 1.2 texels"
    std::string failure; // why it failed; empty when it passed
    ErrorBound bound;
    HitErrorStats stats;
    long long fetchCap = 0;
};

struct StabilityOptions {
    std::vector<std::string> cases; // names to run; empty: all
    int rays = 32;                  // R x R rays per case (and view)
    unsigned seed = 1;              // of the maps that have random texels
};

// Checks hits against the reference under a bound; `figure` names the measured value and the
// limit ("p99 0.31 <= 1.2 texels"), `failure` is empty when the bound holds. Invalid rays (NaN,
// t outside [0, 1]) are left out here: the stability checks fail them on their own.
struct BoundCheck {
    std::string figure;
    std::string failure;
};
BoundCheck checkBound(const ErrorBound& bound, std::span<const TraceResult> hits,
                      std::span<const TraceResult> reference, int width, int height);

// True if every row passed.
bool suitePassed(const std::vector<StabilityRow>& rows);

// Errors: an unknown case name, rays outside [1, 1024], evaluationCancelled(). Failing rows are
// results, not errors. Progress: one unit per case.
Result<std::vector<StabilityRow>> runStabilitySuite(const StabilityOptions& options,
                                                    const EvalControl& control = {});

} // namespace px

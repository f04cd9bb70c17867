// The recommendation's names, its screen-space budget and its sentences for people.
#include "parallax/eval/HitErrorStats.h"
#include "parallax/eval/QuantileBound.h"
#include "parallax/eval/Recommendation.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace px {
namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// "1st", "2nd", "3rd", "4th", "11th", "12th", "13th", "101st", "6101st".
std::string ordinal(std::int64_t n) {
    const std::int64_t tens = n % 100, units = n % 10;
    const char* suffix = tens >= 11 && tens <= 13 ? "th"
                         : units == 1             ? "st"
                         : units == 2             ? "nd"
                         : units == 3             ? "rd"
                                                  : "th";
    return std::to_string(n) + suffix;
}

} // namespace

std::string_view budgetMetricName(BudgetMetric metric) {
    switch (metric) {
    case BudgetMetric::P99:
        return "p99";
    case BudgetMetric::Max:
        return "max";
    case BudgetMetric::NoWrongSurface:
        return "surface";
    }
    return "p99";
}

std::optional<BudgetMetric> parseBudgetMetric(std::string_view name) {
    for (BudgetMetric m : {BudgetMetric::P99, BudgetMetric::Max, BudgetMetric::NoWrongSurface}) {
        if (budgetMetricName(m) == name)
            return m;
    }
    return std::nullopt;
}

std::string_view costMeasureName(CostMeasure cost) {
    switch (cost) {
    case CostMeasure::Fetches:
        return "fetches";
    case CostMeasure::CpuTime:
        return "cpu";
    case CostMeasure::GpuTime:
        return "gpu";
    }
    return "fetches";
}

std::optional<CostMeasure> parseCostMeasure(std::string_view name) {
    for (CostMeasure c : {CostMeasure::Fetches, CostMeasure::CpuTime, CostMeasure::GpuTime}) {
        if (costMeasureName(c) == name)
            return c;
    }
    return std::nullopt;
}

Result<double> texelsPerPixel(const ScreenDensity& d) {
    auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
    if (d.mapWidth <= 0 || d.screenHeight <= 0 || !positive(d.tiling) ||
        !positive(d.surfaceWidth) || !positive(d.distance) || !(d.fovDeg > 0.0 && d.fovDeg < 180.0))
        return Error{"the screen density needs a positive map width, tiling, surface width, "
                     "distance and screen height, and a field of view between 0 and 180 degrees"};
    // Looking straight at the surface: world units per pixel at that distance, times texels per
    // world unit. Grazing views compress one axis further; the budget then errs on the safe side.
    const double worldPerPixel =
        2.0 * d.distance * std::tan(d.fovDeg * std::numbers::pi / 360.0) / d.screenHeight;
    const double texelsPerWorld = d.mapWidth * d.tiling / d.surfaceWidth;
    return worldPerPixel * texelsPerWorld;
}

std::string confidenceStatement(const RecommendConfig& c, std::int64_t n) {
    const std::string conf = format("%.0f%%", c.confidence * 100.0);
    std::string rays = std::to_string(n) + " rays per angle (" +
                       std::to_string(c.azimuthDeg.size()) + " azimuths, " +
                       std::to_string(c.raysPerSide) + "x" + std::to_string(c.raysPerSide) +
                       " jittered origins each)";
    const double fraction = zeroOfNUpperFraction(n, c.confidence);
    switch (c.budget.metric) {
    case BudgetMetric::P99: {
        const std::int64_t k = quantileUpperRank(n, 0.99, c.confidence);
        return rays + ": the budget is judged on the " + ordinal(k) + " smallest error (" +
               format("%.2f", 100.0 * static_cast<double>(k) / static_cast<double>(n)) +
               "th percentile), which is at or above the p99 of all rays with " + conf +
               " confidence";
    }
    case BudgetMetric::Max:
        return rays + ": no sampled ray exceeds the budget, so with " + conf +
               " confidence fewer than " + format("%.3g%%", 100.0 * fraction) + " of all rays do";
    case BudgetMetric::NoWrongSurface:
        return rays + ": the p99 is bounded as for p99, and no sampled ray lands more than " +
               format("%g", kWrongSurfaceTexels) + " texels away, so with " + conf +
               " confidence fewer than " + format("%.3g%%", 100.0 * fraction) +
               " of all rays land on another surface";
    }
    return rays;
}

std::string describe(const Recommendation& r, const RecommendConfig& c) {
    const std::string budget =
        std::string(budgetMetricName(c.budget.metric)) + " <= " + format("%g", c.budget.texels) +
        " texel at every polar angle up to " + format("%g", c.maxPolarDeg) + " degrees";
    if (!r.found)
        return "no setting measured meets " + budget;
    const BenchSetting& s = r.chosen.setting;
    std::string text = std::string(info(s.technique).name) +
                       (s.label.empty() ? "" : " (" + s.label + ")") + " meets " + budget +
                       " at the least cost: ";
    text += c.cost == CostMeasure::GpuTime ? format("%.3g ms per frame", r.chosen.cost)
            : c.cost == CostMeasure::CpuTime
                ? format("%.3g ns per ray on one thread", r.chosen.cost)
                : format("%.3g fetches per ray", r.chosen.cost);
    text += " at its dearest angle";
    return text;
}

} // namespace px

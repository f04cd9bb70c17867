#pragma once
// The work-precision diagram of a bench report as data: per polar angle and cost axis, one series
// per technique across its settings (p99 error against cost), and the Pareto front over all of
// them. Drawing is left to the caller (the CLI's SVG, the editor's interactive panel), which is
// why every point carries the setting it came from: clicking it applies that setting.

#include "parallax/eval/Bench.h"
#include "parallax/eval/Recommendation.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace px {

enum class CostAxis { Fetches, CpuTime, GpuTime };

std::string_view costAxisTitle(CostAxis axis); // "mean fetches per ray", ...

struct WorkPrecisionPoint {
    double cost = 0.0;             // on the panel's cost axis
    double error = 0.0;            // p99 hit error in texels, as measured
    double plotError = 0.0;        // max(error, the chart's floor): what a log axis can show
    double maxError = 0.0;         // the worst ray, texels: p99 hides a few rays far off
    double plotMaxError = 0.0;     // max(maxError, the chart's floor)
    std::int64_t wrongSurface = 0; // rays more than kWrongSurfaceTexels off
    std::size_t row = 0;           // index into BenchReport::pooled
    BenchSetting setting;          // what choosing this point applies
    bool onFront = false;          // no other point of the panel is both cheaper and more accurate
};

struct WorkPrecisionSeries {
    Technique technique = Technique::Exact;
    std::vector<WorkPrecisionPoint> points; // the sweep's order: cheapest setting first
};

// Decades enclosing the data: [10^loExp, 10^hiExp].
struct LogRange {
    int loExp = 0;
    int hiExp = 1;
};

struct PointRef {
    std::size_t series = 0;
    std::size_t point = 0;
};

struct WorkPrecisionPanel {
    double polarDeg = 0.0;
    CostAxis axis = CostAxis::Fetches;
    std::vector<WorkPrecisionSeries> series;
    std::vector<PointRef> front; // the Pareto front, cheapest first
    LogRange costRange;
    LogRange errorRange;

    const WorkPrecisionPoint& at(PointRef ref) const {
        return series[ref.series].points[ref.point];
    }
};

struct WorkPrecisionChart {
    std::vector<double> polarDeg; // panel rows
    std::vector<CostAxis> axes;   // panel columns: fetches, then the times every row has
    double errorFloor = 1e-4;
    std::vector<WorkPrecisionPanel> panels; // row-major: polar index * axes.size() + axis index

    const WorkPrecisionPanel& panel(std::size_t polarIndex, std::size_t axisIndex) const {
        return panels[polarIndex * axes.size() + axisIndex];
    }
};

// Errors below `errorFloor` texels (exact, pyramid) are drawn at the floor. Points whose cost is
// not positive (no log position) are left out.
WorkPrecisionChart makeWorkPrecisionChart(const BenchReport& report, double errorFloor = 1e-4);

// The settings a recommendation measured, at its steepest angle: p99 against mean fetches (what
// the editor shows its choice on). A point's `row` indexes Recommendation::measured; `chosen` is
// set to the chosen setting's point when the recommendation found one.
WorkPrecisionPanel makeRecommendationPanel(const Recommendation& r,
                                           std::optional<PointRef>* chosen = nullptr,
                                           double errorFloor = 1e-4);

} // namespace px

#include "parallax/eval/WorkPrecision.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace px {
namespace {

std::optional<double> costOf(const BenchRow& row, CostAxis axis) {
    switch (axis) {
    case CostAxis::Fetches:
        return row.stats.meanFetches;
    case CostAxis::CpuTime:
        return row.cpuNsPerRay;
    case CostAxis::GpuTime:
        return row.gpuMsPerFrame;
    }
    return std::nullopt;
}

LogRange enclosingDecades(double lo, double hi) {
    LogRange r;
    r.loExp = static_cast<int>(std::floor(std::log10(lo)));
    r.hiExp = static_cast<int>(std::ceil(std::log10(hi)));
    if (r.hiExp <= r.loExp)
        r.hiExp = r.loExp + 1;
    return r;
}

// Which error a front compares: as plotted (errors under the floor are equal: a bench's chart),
// or the errors themselves (a recommendation's chart, to agree with its onFront).
enum class FrontOn { Plotted, Measured };

void markFront(WorkPrecisionPanel& panel, FrontOn on) {
    std::vector<PointRef> all;
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
        for (std::size_t p = 0; p < panel.series[s].points.size(); ++p)
            all.push_back({s, p});
    }
    auto error = [on](const WorkPrecisionPoint& p) {
        return on == FrontOn::Plotted ? p.plotError : p.error;
    };
    std::stable_sort(all.begin(), all.end(), [&](PointRef a, PointRef b) {
        const WorkPrecisionPoint &pa = panel.at(a), &pb = panel.at(b);
        return pa.cost != pb.cost ? pa.cost < pb.cost : error(pa) < error(pb);
    });
    double best = std::numeric_limits<double>::infinity();
    const WorkPrecisionPoint* last = nullptr;
    for (PointRef ref : all) {
        WorkPrecisionPoint& p = panel.series[ref.series].points[ref.point];
        if (error(p) < best) {
            best = error(p);
            p.onFront = true;
            panel.front.push_back(ref);
            last = &p;
        } else if (last && p.cost == last->cost && error(p) == error(*last)) {
            p.onFront = true; // the same figures twice (two caps that cost alike): both on it
        }
    }
}

WorkPrecisionSeries& seriesOf(WorkPrecisionPanel& panel, Technique technique) {
    auto series = std::find_if(panel.series.begin(), panel.series.end(),
                               [&](auto& s) { return s.technique == technique; });
    if (series == panel.series.end())
        series = panel.series.insert(panel.series.end(), {technique, {}});
    return *series;
}

// The ranges over the panel's points, and its front.
void finishPanel(WorkPrecisionPanel& panel, double errorFloor, FrontOn on = FrontOn::Plotted) {
    double costLo = std::numeric_limits<double>::infinity(), costHi = 0.0;
    double errorHi = errorFloor;
    for (const WorkPrecisionSeries& s : panel.series) {
        for (const WorkPrecisionPoint& p : s.points) {
            costLo = std::min(costLo, p.cost);
            costHi = std::max(costHi, p.cost);
            errorHi = std::max({errorHi, p.plotError, p.plotMaxError});
        }
    }
    if (costHi > 0.0)
        panel.costRange = enclosingDecades(costLo, costHi);
    // A decade below the floor, so the points drawn at it stay visible above the axis.
    panel.errorRange = enclosingDecades(errorFloor / 10.0, errorHi);
    markFront(panel, on);
}

} // namespace

std::string_view costAxisTitle(CostAxis axis) {
    switch (axis) {
    case CostAxis::Fetches:
        return "mean fetches per ray";
    case CostAxis::CpuTime:
        return "CPU ns per ray (one thread)";
    case CostAxis::GpuTime:
        return "GPU ms per 1920x1080 frame";
    }
    return "";
}

WorkPrecisionChart makeWorkPrecisionChart(const BenchReport& report, double errorFloor) {
    WorkPrecisionChart chart;
    chart.polarDeg = report.polarDeg;
    chart.errorFloor = errorFloor;
    chart.axes.push_back(CostAxis::Fetches);
    for (CostAxis axis : {CostAxis::CpuTime, CostAxis::GpuTime}) {
        const bool everyRow =
            !report.pooled.empty() &&
            std::all_of(report.pooled.begin(), report.pooled.end(),
                        [&](const BenchRow& r) { return costOf(r, axis).has_value(); });
        if (everyRow)
            chart.axes.push_back(axis);
    }

    for (double polar : chart.polarDeg) {
        for (CostAxis axis : chart.axes) {
            WorkPrecisionPanel panel;
            panel.polarDeg = polar;
            panel.axis = axis;
            for (std::size_t i = 0; i < report.pooled.size(); ++i) {
                const BenchRow& row = report.pooled[i];
                const std::optional<double> cost = costOf(row, axis);
                if (row.polarDeg != polar || !cost || !(*cost > 0.0))
                    continue;
                WorkPrecisionPoint point;
                point.cost = *cost;
                // Against GPU time, the error of what the GPU kernels drew where it was measured.
                point.error = axis == CostAxis::GpuTime && row.gpuStats ? row.gpuStats->p99Error
                                                                        : row.stats.p99Error;
                point.plotError = std::max(point.error, errorFloor);
                point.maxError = row.stats.maxError;
                point.plotMaxError = std::max(point.maxError, errorFloor);
                point.wrongSurface = row.stats.wrongSurface;
                point.row = i;
                point.setting = row.setting;
                seriesOf(panel, row.setting.technique).points.push_back(point);
            }
            finishPanel(panel, errorFloor);
            chart.panels.push_back(std::move(panel));
        }
    }
    return chart;
}

WorkPrecisionPanel makeRecommendationPanel(const Recommendation& r, std::optional<PointRef>* chosen,
                                           double errorFloor) {
    WorkPrecisionPanel panel;
    panel.polarDeg = r.polarDeg.empty() ? 0.0 : r.polarDeg.front();
    panel.axis = CostAxis::Fetches;
    for (std::size_t i = 0; i < r.measured.size(); ++i) {
        const MeasuredSetting& m = r.measured[i];
        // angles end at the first that fails, so the steepest is always there when any is
        if (m.angles.empty() || m.angles.front().polarDeg != panel.polarDeg ||
            !(m.angles.front().meanFetches > 0.0))
            continue;
        const AngleMeasure& a = m.angles.front();
        WorkPrecisionPoint point;
        point.cost = a.meanFetches;
        point.error = a.p99;
        point.plotError = std::max(a.p99, errorFloor);
        point.maxError = a.maxError;
        point.plotMaxError = std::max(a.maxError, errorFloor);
        point.wrongSurface = a.wrongSurface;
        point.row = i;
        point.setting = m.setting;
        WorkPrecisionSeries& series = seriesOf(panel, m.setting.technique);
        series.points.push_back(point);
        if (chosen && r.found && m.setting.technique == r.chosen.setting.technique &&
            m.setting.label == r.chosen.setting.label)
            *chosen = PointRef{static_cast<std::size_t>(&series - panel.series.data()),
                               series.points.size() - 1};
    }
    finishPanel(panel, errorFloor, FrontOn::Measured);
    return panel;
}

} // namespace px

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

void markFront(WorkPrecisionPanel& panel) {
    std::vector<PointRef> all;
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
        for (std::size_t p = 0; p < panel.series[s].points.size(); ++p)
            all.push_back({s, p});
    }
    std::stable_sort(all.begin(), all.end(), [&](PointRef a, PointRef b) {
        const WorkPrecisionPoint &pa = panel.at(a), &pb = panel.at(b);
        return pa.cost != pb.cost ? pa.cost < pb.cost : pa.plotError < pb.plotError;
    });
    double best = std::numeric_limits<double>::infinity();
    for (PointRef ref : all) {
        WorkPrecisionPoint& p = panel.series[ref.series].points[ref.point];
        if (p.plotError < best) {
            best = p.plotError;
            p.onFront = true;
            panel.front.push_back(ref);
        }
    }
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
            double costLo = std::numeric_limits<double>::infinity(), costHi = 0.0;
            double errorHi = errorFloor;
            for (std::size_t i = 0; i < report.pooled.size(); ++i) {
                const BenchRow& row = report.pooled[i];
                const std::optional<double> cost = costOf(row, axis);
                if (row.polarDeg != polar || !cost || !(*cost > 0.0))
                    continue;
                auto series = std::find_if(panel.series.begin(), panel.series.end(), [&](auto& s) {
                    return s.technique == row.setting.technique;
                });
                if (series == panel.series.end())
                    series = panel.series.insert(panel.series.end(), {row.setting.technique, {}});
                WorkPrecisionPoint point;
                point.cost = *cost;
                point.error = row.stats.p99Error;
                point.plotError = std::max(point.error, errorFloor);
                point.maxError = row.stats.maxError;
                point.plotMaxError = std::max(point.maxError, errorFloor);
                point.wrongSurface = row.stats.wrongSurface;
                point.row = i;
                point.setting = row.setting;
                series->points.push_back(point);
                costLo = std::min(costLo, *cost);
                costHi = std::max(costHi, *cost);
                errorHi = std::max({errorHi, point.plotError, point.plotMaxError});
            }
            if (costHi > 0.0)
                panel.costRange = enclosingDecades(costLo, costHi);
            // A decade below the floor, so the points drawn at it stay visible above the axis.
            panel.errorRange = enclosingDecades(errorFloor / 10.0, errorHi);
            markFront(panel);
            chart.panels.push_back(std::move(panel));
        }
    }
    return chart;
}

} // namespace px

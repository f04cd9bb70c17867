// The work-precision chart as data: series per technique, the Pareto front, the error floor,
// and which cost axes exist.

#include "parallax/eval/WorkPrecision.h"

#include <QtTest>

using namespace px;

class WorkPrecisionTest : public QObject {
    Q_OBJECT

private slots:
    void seriesAndFront();
    void floorAndRanges();
    void costAxes();
    void recommendationPanelRingsTheChoice();
};

namespace {

BenchRow row(Technique t, int maxLayers, double fetches, double p99, double polar = 80.0) {
    BenchRow r;
    r.pooled = true;
    r.map = "all";
    r.polarDeg = polar;
    r.setting.technique = t;
    r.setting.params.maxLayers = maxLayers;
    r.setting.label = std::to_string(maxLayers);
    r.stats.meanFetches = fetches;
    r.stats.p99Error = p99;
    return r;
}

BenchReport report() {
    BenchReport r;
    r.polarDeg = {80.0};
    r.pooled = {row(Technique::Pom, 16, 10, 5.0),      row(Technique::Pom, 32, 20, 1.0),
                row(Technique::Pom, 64, 40, 0.5),      row(Technique::RelaxedCone, 24, 15, 0.8),
                row(Technique::Pyramid, 0, 30, 1e-7),  row(Technique::Exact, 0, 80, 0.0),
                row(Technique::Pom, 32, 20, 2.0, 30.0)};
    return r;
}

MeasuredSetting measured(Technique t, const std::string& label, double fetches, double p99,
                         bool meets) {
    MeasuredSetting m;
    m.setting.technique = t;
    m.setting.label = label;
    AngleMeasure a;
    a.polarDeg = 75.0;
    a.meanFetches = fetches;
    a.p99 = p99;
    a.maxError = p99 * 3;
    a.wrongSurface = p99 > 2 ? 7 : 0;
    m.angles.push_back(a);
    if (meets) {
        a.polarDeg = 70.0; // gentler angles follow a meeting steepest one
        m.angles.push_back(a);
    }
    m.meets = meets;
    return m;
}

} // namespace

void WorkPrecisionTest::seriesAndFront() {
    const WorkPrecisionChart chart = makeWorkPrecisionChart(report());
    QCOMPARE(chart.panels.size(), std::size_t(1));
    const WorkPrecisionPanel& p = chart.panel(0, 0);
    QCOMPARE(p.axis, CostAxis::Fetches);
    QCOMPARE(p.series.size(), std::size_t(4));
    QCOMPARE(p.series[0].technique, Technique::Pom);
    QCOMPARE(p.series[0].points.size(), std::size_t(3)); // the 30-degree row is another panel
    // Front, cheapest first: pom 10 (5.0), relaxed 15 (0.8), pyramid 30 (floor). pom 20 (1.0)
    // costs more than relaxed-cone for a larger error; pom 40 and exact are beaten by pyramid.
    QCOMPARE(p.front.size(), std::size_t(3));
    QCOMPARE(p.at(p.front[0]).cost, 10.0);
    QCOMPARE(p.at(p.front[1]).setting.technique, Technique::RelaxedCone);
    QCOMPARE(p.at(p.front[2]).setting.technique, Technique::Pyramid);
    QVERIFY(!p.series[0].points[1].onFront);
    QVERIFY(!p.series[3].points[0].onFront);
    // Each point knows the row and setting it came from.
    const WorkPrecisionPoint& relaxed = p.series[1].points[0];
    QCOMPARE(relaxed.row, std::size_t(3));
    QCOMPARE(relaxed.setting.params.maxLayers, 24);
}

void WorkPrecisionTest::floorAndRanges() {
    const WorkPrecisionChart chart = makeWorkPrecisionChart(report(), 1e-4);
    const WorkPrecisionPanel& p = chart.panel(0, 0);
    const WorkPrecisionPoint& pyramid = p.series[2].points[0];
    QCOMPARE(pyramid.error, 1e-7);
    QCOMPARE(pyramid.plotError, 1e-4);
    QCOMPARE(p.series[3].points[0].plotError, 1e-4);
    QCOMPARE(p.costRange.loExp, 1);
    QCOMPARE(p.costRange.hiExp, 2);
    QCOMPARE(p.errorRange.loExp, -5); // a decade below the floor
    QCOMPARE(p.errorRange.hiExp, 1);
}

void WorkPrecisionTest::costAxes() {
    BenchReport r = report();
    r.polarDeg = {80.0, 30.0};
    QCOMPARE(makeWorkPrecisionChart(r).axes.size(), std::size_t(1));
    for (BenchRow& row : r.pooled)
        row.cpuNsPerRay = 100.0 * row.stats.meanFetches;
    WorkPrecisionChart chart = makeWorkPrecisionChart(r);
    QCOMPARE(chart.axes, (std::vector<CostAxis>{CostAxis::Fetches, CostAxis::CpuTime}));
    QCOMPARE(chart.panels.size(), std::size_t(4));
    QCOMPARE(chart.panel(1, 1).polarDeg, 30.0);
    QCOMPARE(chart.panel(1, 1).axis, CostAxis::CpuTime);
    // A GPU axis only when every row has a GPU time.
    r.pooled[0].gpuMsPerFrame = 3.0;
    QCOMPARE(makeWorkPrecisionChart(r).axes.size(), std::size_t(2));
    // Against GPU time the error is the GPU kernels' own where they were measured.
    for (BenchRow& row : r.pooled)
        row.gpuMsPerFrame = 0.1 * row.stats.meanFetches;
    r.pooled[1].gpuStats = HitErrorStats{};
    r.pooled[1].gpuStats->p99Error = 1.25;
    chart = makeWorkPrecisionChart(r);
    QCOMPARE(chart.axes.back(), CostAxis::GpuTime);
    QCOMPARE(chart.panel(0, 2).series[0].points[1].error, 1.25); // pom 32 at 80 degrees
    QCOMPARE(chart.panel(0, 0).series[0].points[1].error, 1.0);  // the CPU's on the others
}

void WorkPrecisionTest::recommendationPanelRingsTheChoice() {
    Recommendation r;
    r.polarDeg = {75.0, 70.0};
    r.measured = {measured(Technique::Pom, "layers 4-16", 9, 3.0, false),
                  measured(Technique::Pom, "layers 8-32", 18, 0.4, true),
                  measured(Technique::RelaxedCone, "steps 8", 6, 0.3, true),
                  measured(Technique::RelaxedCone, "steps 16", 7, 0.3, true)};
    r.found = true;
    r.chosen = r.measured[2];
    std::optional<PointRef> chosen;
    const WorkPrecisionPanel panel = makeRecommendationPanel(r, &chosen);
    QCOMPARE(panel.polarDeg, 75.0);
    QCOMPARE(panel.axis, CostAxis::Fetches);
    QCOMPARE(panel.series.size(), std::size_t(2));
    QCOMPARE(panel.series[0].points.size(), std::size_t(2));
    QVERIFY(chosen.has_value());
    const WorkPrecisionPoint& c = panel.at(*chosen);
    QCOMPARE(c.setting.technique, Technique::RelaxedCone);
    QCOMPARE(c.setting.label, std::string("steps 8"));
    QCOMPARE(c.row, std::size_t(2));
    QCOMPARE(c.cost, 6.0);
    QCOMPARE(c.maxError, 0.9);
    // The front at the steepest angle: steps 8 (cheapest and best); steps 16 and both POM
    // settings are dominated by it.
    QVERIFY(c.onFront);
    QCOMPARE(panel.front.size(), std::size_t(1));
    QCOMPARE(panel.at(panel.front[0]).setting.label, std::string("steps 8"));
    QCOMPARE(panel.series[0].points[0].wrongSurface, std::int64_t(7));
    QVERIFY(panel.costRange.loExp <= 0 && panel.costRange.hiExp >= 2);

    // Nothing found: no point is ringed, the points are still there.
    r.found = false;
    chosen.reset();
    QCOMPARE(makeRecommendationPanel(r, &chosen).series.size(), std::size_t(2));
    QVERIFY(!chosen.has_value());
}

QTEST_APPLESS_MAIN(WorkPrecisionTest)
#include "WorkPrecisionTest.moc"

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
}

QTEST_APPLESS_MAIN(WorkPrecisionTest)
#include "WorkPrecisionTest.moc"

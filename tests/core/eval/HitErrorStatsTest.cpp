// Accuracy statistics against the reference: percentiles, invalid rays, wrong surfaces, pooling.

#include "parallax/eval/HitErrorStats.h"

#include <QtTest>
#include <cmath>
#include <limits>

using namespace px;

class HitErrorStatsTest : public QObject {
    Q_OBJECT

private slots:
    void nearestRank();
    void errorsInTexelsOfTheMap();
    void invalidRaysAreCountedNotMeasured();
    void wrongSurfaceIsOverTwoTexels();
    void pooledPercentilesAreOfEveryRay();
    void measuredErrorsGiveTheSameTail();
    void documentedExactTechniques();
};

namespace {

TraceResult hit(double u, double v, float t = 0.5f, int fetches = 1) {
    return TraceResult{u, v, t, fetches};
}

} // namespace

void HitErrorStatsTest::nearestRank() {
    std::vector<double> v{5, 1, 4, 2, 3};
    QCOMPARE(nearestRankPercentile(v, 0.5), 3.0);
    QCOMPARE(nearestRankPercentile(v, 1.0), 5.0);
    QCOMPARE(nearestRankPercentile(v, 0.2), 1.0);
    QCOMPARE(nearestRankPercentile(v, 0.21), 2.0);
    std::vector<double> hundred;
    for (int i = 1; i <= 100; ++i)
        hundred.push_back(i);
    QCOMPARE(nearestRankPercentile(hundred, 0.99), 99.0);
    std::vector<double> none;
    QCOMPARE(nearestRankPercentile(none, 0.99), 0.0);
}

void HitErrorStatsTest::errorsInTexelsOfTheMap() {
    // 0.25 uv across a 64 x 16 map: 16 texels in u, 4 texels in v.
    const std::vector<TraceResult> ref{hit(0.5, 0.5), hit(0.5, 0.5)};
    const std::vector<TraceResult> got{hit(0.75, 0.5, 0.5f, 3), hit(0.5, 0.75, 0.5f, 5)};
    const HitErrorStats s = measureHits(got, ref, 64, 16);
    QCOMPARE(s.rays, std::int64_t(2));
    QCOMPARE(s.maxError, 16.0);
    QCOMPARE(s.meanError, 10.0);
    QCOMPARE(s.meanFetches, 4.0);
    QCOMPARE(s.maxFetches, 5);
    QCOMPARE(s.p99Fetches, 5.0);
}

void HitErrorStatsTest::invalidRaysAreCountedNotMeasured() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<TraceResult> ref(4, hit(0.5, 0.5));
    const std::vector<TraceResult> got{hit(nan, 0.5), hit(0.5, 0.5, 1.5f), hit(0.5, 0.5, -0.1f),
                                       hit(0.5, 0.5)};
    const HitErrorStats s = measureHits(got, ref, 8, 8);
    QCOMPARE(s.invalid, std::int64_t(3));
    QCOMPARE(s.rays, std::int64_t(4));
    QCOMPARE(s.maxError, 0.0);
    QVERIFY(std::isfinite(s.meanError));
}

void HitErrorStatsTest::wrongSurfaceIsOverTwoTexels() {
    const std::vector<TraceResult> ref(3, hit(0.0, 0.0));
    // 2 texels exactly is the same surface; 2.1 is another.
    const std::vector<TraceResult> got{hit(2.0 / 10, 0.0), hit(2.1 / 10, 0.0), hit(0.0, 0.5)};
    const HitErrorStats s = measureHits(got, ref, 10, 10);
    QCOMPARE(s.wrongSurface, std::int64_t(2));
}

void HitErrorStatsTest::pooledPercentilesAreOfEveryRay() {
    // One trace with 99 exact rays and one far off, one with 100 rays all 1 texel off: the pooled
    // p99 is a percentile of the 200 rays, not a mean of the two p99s.
    std::vector<TraceResult> refA(100, hit(0.0, 0.0)), gotA = refA;
    gotA[7] = hit(0.5, 0.0);
    std::vector<TraceResult> refB(100, hit(0.0, 0.0)), gotB(100, hit(0.01, 0.0));
    HitErrorAccumulator pooled;
    pooled.add(gotA, refA, 100, 100);
    pooled.add(gotB, refB, 100, 100);
    const HitErrorStats s = pooled.stats();
    QCOMPARE(s.rays, std::int64_t(200));
    QCOMPARE(s.p99Error, 1.0);
    QCOMPARE(s.maxError, 50.0);
    QCOMPARE(measureHits(gotA, refA, 100, 100).p99Error, 0.0);
}

// The editor feeds errors it measured itself: 99 rays on the surface and one 141 texels off keep
// p99 small, and the max and the wrong-surface count are what shows that ray.
void HitErrorStatsTest::measuredErrorsGiveTheSameTail() {
    HitErrorAccumulator acc;
    for (int k = 0; k < 99; ++k)
        acc.addError(0.01, 4);
    acc.addError(141.0, 30);
    acc.addError(std::numeric_limits<double>::quiet_NaN(), 2);
    const HitErrorStats s = acc.stats();
    QCOMPARE(s.rays, std::int64_t(101));
    QCOMPARE(s.invalid, std::int64_t(1));
    QCOMPARE(s.p99Error, 0.01);
    QCOMPARE(s.maxError, 141.0);
    QCOMPARE(s.wrongSurface, std::int64_t(1));
    QCOMPARE(s.maxFetches, 30);
}

void HitErrorStatsTest::documentedExactTechniques() {
    QVERIFY(isDocumentedExact(Technique::Cone));
    QVERIFY(isDocumentedExact(Technique::Pyramid));
    QVERIFY(isDocumentedExact(Technique::Exact));
    QVERIFY(isDocumentedExact(Technique::RelaxedCone));
    QVERIFY(!isDocumentedExact(Technique::Pom));
}

QTEST_APPLESS_MAIN(HitErrorStatsTest)
#include "HitErrorStatsTest.moc"

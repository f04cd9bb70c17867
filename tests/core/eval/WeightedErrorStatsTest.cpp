// Area-weighted error statistics (the editor's readout): equal weights give the bench's figures
// exactly, and an integer weight counts as that many equal samples.

#include "parallax/eval/WeightedErrorStats.h"

#include "parallax/eval/HitErrorStats.h"

#include <QtTest>
#include <cmath>
#include <limits>
#include <random>

using namespace px;

class WeightedErrorStatsTest : public QObject {
    Q_OBJECT

private slots:
    void equalWeightsAreTheBenchsFigures_data();
    void equalWeightsAreTheBenchsFigures();
    void anIntegerWeightIsThatManySamples_data();
    void anIntegerWeightIsThatManySamples();
    void badSamplesAreLeftOut();
};

namespace {

// Errors with a heavy tail and ties (the rendered errors have both): a few far off, many equal.
std::vector<double> randomErrors(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> near(0.0, 0.5), far(2.0, 40.0), pick(0.0, 1.0);
    std::vector<double> errors;
    errors.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double p = pick(rng);
        errors.push_back(p < 0.03 ? far(rng) : p < 0.2 ? 0.25 : near(rng));
    }
    return errors;
}

void addSeeds() {
    QTest::addColumn<unsigned>("seed");
    const unsigned run = std::random_device{}();
    for (unsigned seed : {1u, 2u, 3u, 17u, run})
        QTest::addRow("seed%u", seed) << seed;
}

} // namespace

void WeightedErrorStatsTest::equalWeightsAreTheBenchsFigures_data() {
    addSeeds();
}

void WeightedErrorStatsTest::equalWeightsAreTheBenchsFigures() {
    QFETCH(unsigned, seed);
    std::mt19937 rng(seed);
    for (int n : {1, 2, 99, 100, 101, 1000, 4097}) {
        const std::vector<double> errors = randomErrors(rng, n);
        HitErrorAccumulator bench;
        WeightedErrorAccumulator weighted;
        for (double e : errors) {
            bench.addError(e, 1);
            weighted.add(e, 0.125); // any equal weight: a pixel's area in tiles
        }
        const HitErrorStats b = bench.stats();
        const WeightedErrorStats w = weighted.stats();
        const QByteArray where =
            QByteArray("seed ") + QByteArray::number(seed) + " n " + QByteArray::number(n);
        QVERIFY2(w.p99Error == b.p99Error, where.constData());
        QVERIFY2(w.maxError == b.maxError, where.constData());
        QVERIFY2(std::abs(w.meanError - b.meanError) <= 1e-12 * (1.0 + b.meanError),
                 where.constData());
        QVERIFY2(std::abs(w.wrongSurfaceShare - double(b.wrongSurface) / n) <= 1e-12,
                 where.constData());
        QCOMPARE(w.samples, std::int64_t(n));
    }
}

void WeightedErrorStatsTest::anIntegerWeightIsThatManySamples_data() {
    addSeeds();
}

void WeightedErrorStatsTest::anIntegerWeightIsThatManySamples() {
    QFETCH(unsigned, seed);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> copies(1, 9);
    const std::vector<double> errors = randomErrors(rng, 700);
    WeightedErrorAccumulator weighted;
    std::vector<double> repeated;
    double sum = 0.0;
    for (double e : errors) {
        const int k = copies(rng);
        weighted.add(e, k);
        repeated.insert(repeated.end(), static_cast<std::size_t>(k), e);
        sum += e * k;
    }
    const WeightedErrorStats w = weighted.stats();
    std::vector<double> sorted = repeated;
    QVERIFY2(w.p99Error == nearestRankPercentile(sorted, 0.99), qPrintable(QString::number(seed)));
    QVERIFY(std::abs(w.meanError - sum / repeated.size()) <= 1e-12 * (1.0 + w.meanError));
    QCOMPARE(w.weight, static_cast<double>(repeated.size()));
    // The tail's weight, not its count: the same errors with the far ones weighing 100 times
    // more move the p99 onto them.
    WeightedErrorAccumulator heavyTail;
    double farthest = 0.0;
    for (double e : errors) {
        heavyTail.add(e, e > kWrongSurfaceTexels ? 100.0 : 1.0);
        farthest = std::max(farthest, e);
    }
    QVERIFY(heavyTail.stats().p99Error > kWrongSurfaceTexels);
    QCOMPARE(heavyTail.stats().maxError, farthest);
}

void WeightedErrorStatsTest::badSamplesAreLeftOut() {
    WeightedErrorAccumulator a;
    a.add(1.0, 1.0);
    a.add(std::numeric_limits<double>::quiet_NaN(), 1.0);
    a.add(50.0, 0.0);
    a.add(50.0, -1.0);
    a.add(50.0, std::numeric_limits<double>::infinity());
    const WeightedErrorStats s = a.stats();
    QCOMPARE(s.samples, std::int64_t(1));
    QCOMPARE(s.maxError, 1.0);
    QCOMPARE(s.p99Error, 1.0);
    QCOMPARE(WeightedErrorAccumulator().stats().p99Error, 0.0);
}

QTEST_APPLESS_MAIN(WeightedErrorStatsTest)
#include "WeightedErrorStatsTest.moc"

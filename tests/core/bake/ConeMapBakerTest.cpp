// Conservative (Quick) cone maps against the brute-force oracle and against sampled surface
// points; the 3x3 minimum, quantisation, cancellation.

#include "parallax/bake/ConeMapBaker.h"

#include "ConeChecks.h"
#include "parallax/bake/ConeMapFinish.h"
#include "parallax/bake/ConeMapReference.h"
#include "parallax/sample/ProceduralMaps.h"

// TBB before Qt: Qt's `emit` macro breaks tbb/profiling.h.
// clang-format off
#include <tbb/task_arena.h>
// clang-format on
#include <QtTest>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <random>

using namespace px;

namespace {

struct Case {
    ProceduralMap map;
    int width, height;
};

// Odd sizes, 1x1, 1xN and Nx1, and the shapes that stress cones (needles, steps, noise).
const Case kCases[] = {
    {ProceduralMap::Random, 1, 1},   {ProceduralMap::Random, 1, 7},
    {ProceduralMap::Random, 9, 1},   {ProceduralMap::Random, 2, 2},
    {ProceduralMap::Random, 5, 3},   {ProceduralMap::Noise, 16, 16},
    {ProceduralMap::Random, 13, 11}, {ProceduralMap::Spikes, 17, 19},
    {ProceduralMap::Bricks, 24, 24}, {ProceduralMap::Step, 12, 9},
    {ProceduralMap::Checker, 8, 8},  {ProceduralMap::Cracks, 15, 15},
    {ProceduralMap::Ramp, 10, 6},    {ProceduralMap::Flat, 6, 6},
    {ProceduralMap::Stones, 20, 14},
};

QByteArray caseName(const Case& c, WrapMode wrap) {
    return QByteArray::number(static_cast<int>(c.map)) + " " + QByteArray::number(c.width) + "x" +
           QByteArray::number(c.height) + " " + toString(wrap).data();
}

} // namespace

class ConeMapBakerTest : public QObject {
    Q_OBJECT

private slots:
    void quickNeverWiderThanBruteForce_data();
    void quickNeverWiderThanBruteForce();
    void bruteForceIsConservativeAndTight_data();
    void bruteForceIsConservativeAndTight();
    void quickIsConservativeOnSampledPoints();
    void checkerFindsWideCones();
    void rampConeIsItsSlope();
    void neighbourhoodMinimum();
    void quantisationRoundsDown();
    void bakeConeMapPostProcesses();
    void cancelsAndReportsProgress();
    void relaxedConeStopsWithinATileRow();
    void rejectsEmptyField();
    void sameRunToRunAndForAnyThreadCount();
};

void ConeMapBakerTest::quickNeverWiderThanBruteForce_data() {
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("wrap");
    for (int i = 0; i < static_cast<int>(std::size(kCases)); ++i) {
        for (int w = 0; w < 2; ++w)
            QTest::newRow(caseName(kCases[i], WrapMode(w)).constData()) << i << w;
    }
}

// c_quick <= c_brute at every texel, exactly (same float arithmetic on nested regions), raw and
// after the 3x3 minimum; and Quick stays within a sane factor of the oracle.
void ConeMapBakerTest::quickNeverWiderThanBruteForce() {
    QFETCH(int, index);
    QFETCH(int, wrap);
    const Case& k = kCases[index];
    const WrapMode mode = WrapMode(wrap);
    const HeightField field = makeProceduralMap(k.map, k.width, k.height, 11);
    Result<ConeMap> quick = bakeQuickConeMap(field, mode);
    QVERIFY(quick.ok());
    ConeMap brute = bakeConservativeConesBruteForce(field, mode);
    QCOMPARE(quick->width, k.width);
    QCOMPARE(quick->height, k.height);
    double sumQuick = 0, sumBrute = 0;
    for (std::size_t i = 0; i < brute.sqrtRatio.size(); ++i) {
        const float q = quick->sqrtRatio[i], b = brute.sqrtRatio[i];
        QVERIFY2(q >= 0.0f && q <= b,
                 qPrintable(QString("texel %1: quick %2 > brute %3").arg(i).arg(q).arg(b)));
        sumQuick += q * q;
        sumBrute += b * b;
    }
    QVERIFY(sumQuick >= 0.5 * sumBrute);
    ConeMap post = *quick;
    applyNeighbourhoodMinimum(post, mode);
    applyNeighbourhoodMinimum(brute, mode);
    for (std::size_t i = 0; i < brute.sqrtRatio.size(); ++i)
        QVERIFY(post.sqrtRatio[i] <= brute.sqrtRatio[i]);
    if (k.map == ProceduralMap::Flat || (k.width == 1 && k.height == 1)) {
        for (float g : quick->sqrtRatio)
            QCOMPARE(g, 1.0f); // nothing rises above any apex
    }
}

void ConeMapBakerTest::bruteForceIsConservativeAndTight_data() {
    quickNeverWiderThanBruteForce_data();
}

// The oracle against the definition, checked on 8x8 points per cell: no sampled point is inside
// any cone (conservative), and the nearest sampled point is within 4% of the cone (tight; the
// sampling, not the oracle, sets that margin).
void ConeMapBakerTest::bruteForceIsConservativeAndTight() {
    QFETCH(int, index);
    QFETCH(int, wrap);
    const Case& k = kCases[index];
    const WrapMode mode = WrapMode(wrap);
    const HeightField field = makeProceduralMap(k.map, k.width, k.height, 11);
    const ConeMap brute = bakeConservativeConesBruteForce(field, mode);
    long violations = 0, loose = 0, limited = 0;
    double worstLoose = 1.0;
    for (int y = 0; y < field.height; ++y) {
        for (int x = 0; x < field.width; ++x) {
            const double c = brute.ratio(x, y);
            const test::ConeCheck check = test::checkConservative(field, mode, x, y, c, 8);
            violations += check.violations;
            if (c < 0.999) {
                ++limited;
                worstLoose = std::max(worstLoose, check.minRatio / c);
                loose += check.minRatio > 1.04 * c;
            }
        }
    }
    QVERIFY2(violations == 0,
             qPrintable(QString("%1 sampled points inside cones").arg(violations)));
    QVERIFY2(loose == 0, qPrintable(QString("%1 of %2 cones more than 4% narrower than the nearest "
                                            "sampled point (worst x%3)")
                                        .arg(loose)
                                        .arg(limited)
                                        .arg(worstLoose)));
}

// The fast baker on maps large enough for several pyramid levels, against sampled points.
void ConeMapBakerTest::quickIsConservativeOnSampledPoints() {
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        for (ProceduralMap map :
             {ProceduralMap::Noise, ProceduralMap::Rivets, ProceduralMap::Random}) {
            const HeightField field = makeProceduralMap(map, 45, 37, 3);
            const ConeMap cones = *bakeQuickConeMap(field, mode);
            long violations = 0;
            for (int y = 0; y < field.height; y += 2) {
                for (int x = 0; x < field.width; x += 2)
                    violations +=
                        test::checkConservative(field, mode, x, y, cones.ratio(x, y), 4).violations;
            }
            QCOMPARE(violations, 0L);
        }
    }
}

// The checker itself: cones 3% wider than the oracle's must contain surface points.
void ConeMapBakerTest::checkerFindsWideCones() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 16, 16, 11);
    const ConeMap brute = bakeConservativeConesBruteForce(field, WrapMode::Repeat);
    long inside = 0, limited = 0;
    for (int y = 0; y < field.height; ++y) {
        for (int x = 0; x < field.width; ++x) {
            if (brute.ratio(x, y) < 0.9) {
                ++limited;
                inside += test::checkConservative(field, WrapMode::Repeat, x, y,
                                                  brute.ratio(x, y) * 1.03, 8)
                              .violations > 0;
            }
        }
    }
    QVERIFY(limited > 100);
    QVERIFY2(inside > limited * 9 / 10, qPrintable(QString("%1 of %2").arg(inside).arg(limited)));
}

// On a plane the cone is exactly 1 / slope wherever the plane rises away from the apex (the
// cells around the apex are bounded exactly, and the oracle everywhere).
void ConeMapBakerTest::rampConeIsItsSlope() {
    const int W = 8, H = 5;
    HeightField field(W, H);
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x)
            field.at(x, y) = static_cast<float>(x) / (W - 1); // slope 8/7 per uv
    }
    const ConeMap brute = bakeConservativeConesBruteForce(field, WrapMode::Clamp);
    const ConeMap quick = *bakeQuickConeMap(field, WrapMode::Clamp);
    const double expected = 7.0 / 8.0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W - 1; ++x) {
            QVERIFY(std::abs(brute.ratio(x, y) / expected - 1.0) < 1e-5);
            // The apex cells alone give the exact cone; region growing may only narrow it.
            QVERIFY(quick.ratio(x, y) <= brute.ratio(x, y));
            QVERIFY(quick.ratio(x, y) > 0.3 * expected);
        }
        QCOMPARE(brute.g(W - 1, y), 1.0f); // the top: nothing higher
    }
}

void ConeMapBakerTest::neighbourhoodMinimum() {
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        for (auto [w, h] : {std::pair{1, 1}, {1, 5}, {6, 1}, {2, 3}, {70, 9}, {13, 130}}) {
            ConeMap cones(ConeKind::Conservative, w, h);
            for (std::size_t i = 0; i < cones.sqrtRatio.size(); ++i)
                cones.sqrtRatio[i] = static_cast<float>((i * 7919) % 101) / 100.0f;
            const ConeMap original = cones;
            applyNeighbourhoodMinimum(cones, mode);
            for (int y = 0; y < h; ++y) {
                for (int x = 0; x < w; ++x) {
                    float m = original.g(x, y);
                    for (int dy = -1; dy <= 1; ++dy) {
                        for (int dx = -1; dx <= 1; ++dx)
                            m = std::min(m, original.g(wrapIndex(x + dx, w, mode),
                                                       wrapIndex(y + dy, h, mode)));
                    }
                    QCOMPARE(cones.g(x, y), m);
                }
            }
        }
    }
}

void ConeMapBakerTest::quantisationRoundsDown() {
    ConeMap cones(ConeKind::Conservative, 1000, 1);
    for (int i = 0; i < 1000; ++i)
        cones.sqrtRatio[i] = static_cast<float>(i) / 999.0f;
    for (int levels : {255, 65535}) {
        ConeMap q = cones;
        quantiseDown(q, levels);
        for (int i = 0; i < 1000; ++i) {
            const float g = cones.sqrtRatio[i], s = q.sqrtRatio[i];
            QVERIFY(s <= g);
            QVERIFY(g - s < 1.0f / levels + 1e-6f);
            QCOMPARE(std::round(s * levels), s * levels); // a whole step
        }
        QCOMPARE(q.sqrtRatio[999], 1.0f);
    }
}

void ConeMapBakerTest::bakeConeMapPostProcesses() {
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 33, 21, 4);
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        ConeMap raw = *bakeQuickConeMap(field, mode);
        applyNeighbourhoodMinimum(raw, mode);
        const ConeMap baked = bakeConeMap(field, mode, ConeKind::Conservative);
        QCOMPARE(baked.kind, ConeKind::Conservative);
        QVERIFY(baked.sqrtRatio == raw.sqrtRatio);
    }
}

void ConeMapBakerTest::cancelsAndReportsProgress() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 96, 96);
    for (ConeKind kind : {ConeKind::Conservative, ConeKind::Relaxed}) {
        std::vector<float> seen;
        BakeControl control;
        control.progress = [&](float p) { seen.push_back(p); };
        QVERIFY(bakeConeMap(field, WrapMode::Repeat, kind, control).ok());
        QVERIFY(seen.size() > 2);
        QCOMPARE(seen.back(), 1.0f);
        QVERIFY(std::is_sorted(seen.begin(), seen.end()));

        // Cancelled from inside the bake, as a UI thread would.
        std::atomic<bool> stop{false};
        control.cancel = &stop;
        control.progress = [&](float p) {
            if (p > 0.2f)
                stop = true;
        };
        const Result<ConeMap> cancelled = bakeConeMap(field, WrapMode::Repeat, kind, control);
        QVERIFY(!cancelled.ok());
        QVERIFY(isCancelled(cancelled.error()));
    }
}

// The relaxed-cone bake polls the cancel flag and reports progress per tile row (4 texel rows):
// once cancelled, each thread finishes at most the row it is in. Measured in work, not time: the
// progress reported after the request grows by at most one row per thread (plus a report step).
void ConeMapBakerTest::relaxedConeStopsWithinATileRow() {
    // Tall and narrow: many cheap tile rows, as an 8192² map has (TBB's ranges grow with them).
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 32, 4096);
    // Work as the baker counts it: a cell row of the set-up 1, a tile row 200.
    const double row = 200.0 / (4096 + 1024 * 200);
    std::atomic<bool> stop{false};
    float requestedAt = -1.0f, last = 0.0f;
    int reports = 0;
    BakeControl control;
    control.cancel = &stop;
    control.progress = [&](float p) {
        ++reports;
        last = p;
        if (p >= 0.1f && requestedAt < 0.0f) {
            requestedAt = p;
            stop = true;
        }
    };
    const Result<ConeMap> cancelled = bakeRelaxedConeMap(field, WrapMode::Repeat, control);
    QVERIFY(!cancelled.ok() && isCancelled(cancelled.error()));
    QVERIFY(requestedAt >= 0.1f);
    // Reports from the first tenth: every few rows, not once per TBB range.
    QVERIFY2(reports >= 5, qPrintable(QString::number(reports)));
    const int threads = tbb::this_task_arena::max_concurrency();
    const double bound = requestedAt + (threads + 1) * row + 1.0 / 200;
    QVERIFY2(last <= bound, qPrintable(QStringLiteral("requested at %1, reached %2, bound %3")
                                           .arg(requestedAt)
                                           .arg(last)
                                           .arg(bound)));
}

// Both bakers, post-processed as the techniques use them: the same map on every run and for 1, 2,
// 3 and 8 threads (more than this machine's cores: tiles and rows interleave otherwise), on a map
// with several tile rows per thread and odd edges, both wraps, seeds varied per run
// (PX_TEST_SEED=N repeats one).
void ConeMapBakerTest::sameRunToRunAndForAnyThreadCount() {
    const char* given = std::getenv("PX_TEST_SEED");
    const unsigned seed = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                                : std::random_device{}() % 100000u;
    qInfo("map seed %u (PX_TEST_SEED=%u repeats it)", seed, seed);
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 131, 70, seed);
    for (ConeKind kind : {ConeKind::Conservative, ConeKind::Relaxed}) {
        for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
            const ConeMap first = bakeConeMap(field, mode, kind);
            QVERIFY(bakeConeMap(field, mode, kind).sqrtRatio == first.sqrtRatio);
            for (int threads : {1, 2, 3, 8}) {
                tbb::task_arena arena(threads);
                ConeMap again;
                arena.execute([&] { again = bakeConeMap(field, mode, kind); });
                QVERIFY2(again.sqrtRatio == first.sqrtRatio,
                         qPrintable(QString("%1 threads, %2, %3")
                                        .arg(threads)
                                        .arg(kind == ConeKind::Relaxed ? "relaxed" : "cone")
                                        .arg(toString(mode).data())));
            }
        }
    }
}

void ConeMapBakerTest::rejectsEmptyField() {
    QVERIFY(!bakeQuickConeMap(HeightField{}, WrapMode::Repeat).ok());
    QVERIFY(!bakeRelaxedConeMap(HeightField{}, WrapMode::Clamp).ok());
    QCOMPARE(bakeConeMap(HeightField{}, WrapMode::Repeat, ConeKind::Conservative).width, 0);
}

QTEST_APPLESS_MAIN(ConeMapBakerTest)
#include "ConeMapBakerTest.moc"

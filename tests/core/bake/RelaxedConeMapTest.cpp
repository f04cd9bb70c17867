// Relaxed cone maps: the fast baker against the ring scan (the same cones, to the bit, whatever
// the search), wider than conservative cones, the same for any thread count and without the
// seeds the CPU gives its tiles (as the GPU runs them), and the relaxed property on sampled rays,
// on the samples and on the adversarial maps with seeds varied per run (PX_TEST_SEED=N repeats
// one), with the original GPU Gems 3 pre-process as a negative control.

#include "ConeChecks.h"
#include "bake/BakeKernel.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/ConeMapReference.h"
#include "parallax/sample/ProceduralMaps.h"

// TBB before Qt: Qt's `emit` macro breaks tbb/profiling.h.
// clang-format off
#include <tbb/task_arena.h>
// clang-format on
#include <QtTest>
#include <cmath>
#include <cstdlib>
#include <random>

using namespace px;

namespace {

struct Case {
    ProceduralMap map;
    int width, height;
};

// The last three, clamped, have one cell and a one-level pyramid (they crashed the fast baker).
const Case kCases[] = {
    {ProceduralMap::Random, 1, 1},   {ProceduralMap::Random, 1, 6},
    {ProceduralMap::Random, 7, 1},   {ProceduralMap::Random, 3, 2},
    {ProceduralMap::Noise, 19, 16},  {ProceduralMap::Random, 13, 11},
    {ProceduralMap::Spikes, 17, 17}, {ProceduralMap::Bricks, 24, 20},
    {ProceduralMap::Stones, 21, 21}, {ProceduralMap::Checker, 8, 6},
    {ProceduralMap::Step, 9, 9},     {ProceduralMap::Flat, 4, 4},
    {ProceduralMap::Random, 2, 2},   {ProceduralMap::Random, 1, 2},
    {ProceduralMap::Random, 2, 1},
};

// The adversarial classes (AdversarialMaps.h), small: the seed changes from run to run.
const Case kAdversarial[] = {
    {ProceduralMap::SpikeFlat, 40, 6}, {ProceduralMap::Walls, 24, 20},
    {ProceduralMap::Treads, 36, 12},   {ProceduralMap::Pits, 22, 22},
    {ProceduralMap::Terraces, 26, 24}, {ProceduralMap::Outliers, 24, 24},
    {ProceduralMap::Jpeg, 24, 24},     {ProceduralMap::Rivets, 30, 27},
};

unsigned runSeed() {
    static const unsigned seed = [] {
        const char* given = std::getenv("PX_TEST_SEED");
        const unsigned s = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                                 : std::random_device{}() % 100000u;
        qInfo("adversarial map seed %u (PX_TEST_SEED=%u repeats it)", s, s);
        return s;
    }();
    return seed;
}

// The relaxed map as the GPU bakes it: the kernel over 4 x 4 tiles, each alone (no seeds from
// its neighbours), in any order.
ConeMap bakeUnseeded(const HeightField& field, WrapMode wrap) {
    const bake::FallPyramid fall(field, wrap);
    const bake::EdgeStrips strips(field, wrap);
    bake::BakeKernel kernel(field, wrap);
    kernel.fall = &fall;
    kernel.strips = &strips;
    kernel.pxFallTop = fall.top();
    kernel.pxFallUnit = fall.unit();
    for (glm::ivec3& seed : kernel.pxSeedRow)
        seed = glm::ivec3(0);
    for (glm::ivec3& seed : kernel.pxSeedColumn)
        seed = glm::ivec3(0);
    ConeMap cones(ConeKind::Relaxed, field.width, field.height);
    // Bottom-up, right to left: another order than the CPU baker's.
    for (int ty = (field.height - 1) / PX_TILE_H * PX_TILE_H; ty >= 0; ty -= PX_TILE_H) {
        for (int tx = (field.width - 1) / PX_TILE_W * PX_TILE_W; tx >= 0; tx -= PX_TILE_W) {
            const int tw = std::min(PX_TILE_W, field.width - tx);
            const int th = std::min(PX_TILE_H, field.height - ty);
            kernel.pxRelaxedTile(glm::ivec2(tx, ty), glm::ivec2(tw, th));
            for (int k = 0; k < tw * th; ++k)
                cones.g(tx + k % tw, ty + k / tw) = kernel.pxRelaxedResult(k);
        }
    }
    return cones;
}

QByteArray caseName(const Case& c, WrapMode wrap) {
    return QByteArray::number(static_cast<int>(c.map)) + " " + QByteArray::number(c.width) + "x" +
           QByteArray::number(c.height) + " " + toString(wrap).data();
}

} // namespace

class RelaxedConeMapTest : public QObject {
    Q_OBJECT

private slots:
    void fastMatchesRingScan_data();
    void fastMatchesRingScan();
    void adversarialMatchRingScan_data();
    void adversarialMatchRingScan();
    void sameForAnyThreadCount();
    void relaxedPropertyHolds();
    void relaxedPropertyHoldsOnAdversarialMaps();
    void gpuGemsConesLeaveTheSolid();
};

void RelaxedConeMapTest::fastMatchesRingScan_data() {
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("wrap");
    for (int i = 0; i < static_cast<int>(std::size(kCases)); ++i) {
        for (int w = 0; w < 2; ++w)
            QTest::newRow(caseName(kCases[i], WrapMode(w)).constData()) << i << w;
    }
}

// Every cone is the least bound of one cell (shaders/bake/cells.glsl), which does not
// depend on the order cells are met in: the pyramid search, seeded or not, finds the ring scan's
// cones to the bit. Relaxed cones are never narrower than the conservative ones (the oracle's
// within the per-cell tolerance of 3%).
void checkAgainstRingScan(const HeightField& field, WrapMode mode) {
    Result<ConeMap> fast = bakeRelaxedConeMap(field, mode);
    QVERIFY(fast.ok());
    QCOMPARE(fast->kind, ConeKind::Relaxed);
    const ConeMap ring = bakeRelaxedConesBruteForce(field, mode);
    const ConeMap unseeded = bakeUnseeded(field, mode);
    const ConeMap quick = *bakeQuickConeMap(field, mode);
    const ConeMap brute = bakeConservativeConesBruteForce(field, mode);
    for (std::size_t i = 0; i < ring.sqrtRatio.size(); ++i) {
        const double f = fast->sqrtRatio[i], r = ring.sqrtRatio[i];
        QVERIFY2(f == r, qPrintable(QString("texel %1: %2 vs %3").arg(i).arg(f).arg(r)));
        QVERIFY2(unseeded.sqrtRatio[i] == fast->sqrtRatio[i],
                 qPrintable(QString("texel %1: unseeded %2 vs seeded %3")
                                .arg(i)
                                .arg(unseeded.sqrtRatio[i])
                                .arg(f)));
        QVERIFY(fast->sqrtRatio[i] >= quick.sqrtRatio[i]);
        QVERIFY(f * f >= 0.97 * brute.ratio(static_cast<int>(i % field.width),
                                            static_cast<int>(i / field.width)));
    }
}

void RelaxedConeMapTest::fastMatchesRingScan() {
    QFETCH(int, index);
    QFETCH(int, wrap);
    const Case& k = kCases[index];
    checkAgainstRingScan(makeProceduralMap(k.map, k.width, k.height, 5), WrapMode(wrap));
}

void RelaxedConeMapTest::adversarialMatchRingScan_data() {
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("wrap");
    for (int i = 0; i < static_cast<int>(std::size(kAdversarial)); ++i) {
        for (int w = 0; w < 2; ++w)
            QTest::newRow(caseName(kAdversarial[i], WrapMode(w)).constData()) << i << w;
    }
}

void RelaxedConeMapTest::adversarialMatchRingScan() {
    QFETCH(int, index);
    QFETCH(int, wrap);
    const Case& k = kAdversarial[index];
    checkAgainstRingScan(makeProceduralMap(k.map, k.width, k.height, runSeed()), WrapMode(wrap));
}

// One thread and every core give the same map (tiles are independent of the order they run in).
void RelaxedConeMapTest::sameForAnyThreadCount() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 150, 97, runSeed());
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        const ConeMap all = *bakeRelaxedConeMap(field, mode);
        tbb::task_arena one(1);
        ConeMap single;
        one.execute([&] { single = *bakeRelaxedConeMap(field, mode); });
        QVERIFY(single.sqrtRatio == all.sqrtRatio);
    }
}

// Rays from each apex's column that stay inside its relaxed cone never leave the solid once
// inside (1e-6 of height units, the checker's own sampling noise), on the raw and on the
// post-processed maps.
void RelaxedConeMapTest::relaxedPropertyHolds() {
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        for (ProceduralMap map : {ProceduralMap::Noise, ProceduralMap::Random,
                                  ProceduralMap::Stones, ProceduralMap::Spikes}) {
            const HeightField field = makeProceduralMap(map, 16, 15, 8);
            const ConeMap cones = *bakeRelaxedConeMap(field, mode);
            long rays = 0, left = 0;
            double worst = 0;
            for (int y = 0; y < field.height; ++y) {
                for (int x = 0; x < field.width; ++x) {
                    const test::ConeCheck check =
                        test::checkRelaxed(field, mode, x, y, cones.ratio(x, y), 1e-6);
                    rays += check.points;
                    left += check.violations;
                    worst = std::max(worst, check.worst);
                }
            }
            QVERIFY(rays > 30000);
            QVERIFY2(left == 0,
                     qPrintable(QString("map %1 %2: %3 of %4 rays left the solid, by up to %5")
                                    .arg(static_cast<int>(map))
                                    .arg(toString(mode).data())
                                    .arg(left)
                                    .arg(rays)
                                    .arg(worst)));
        }
    }
}

// The relaxed property on the adversarial classes, both wraps, this run's seed.
void RelaxedConeMapTest::relaxedPropertyHoldsOnAdversarialMaps() {
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        for (ProceduralMap map :
             {ProceduralMap::SpikeFlat, ProceduralMap::Walls, ProceduralMap::Pits,
              ProceduralMap::Terraces, ProceduralMap::Outliers}) {
            const HeightField field = makeProceduralMap(map, 14, 12, runSeed());
            const ConeMap cones = *bakeRelaxedConeMap(field, mode);
            long rays = 0, left = 0;
            double worst = 0;
            for (int y = 0; y < field.height; ++y) {
                for (int x = 0; x < field.width; ++x) {
                    const test::ConeCheck check =
                        test::checkRelaxed(field, mode, x, y, cones.ratio(x, y), 1e-6);
                    rays += check.points;
                    left += check.violations;
                    worst = std::max(worst, check.worst);
                }
            }
            QVERIFY2(left == 0,
                     qPrintable(QString("map %1 %2 seed %3: %4 of %5 rays left the solid, by up "
                                        "to %6")
                                    .arg(static_cast<int>(map))
                                    .arg(toString(mode).data())
                                    .arg(runSeed())
                                    .arg(left)
                                    .arg(rays)
                                    .arg(worst)));
        }
    }
}

// Negative control: the GPU Gems 3 pre-process (rays from the top of the column only, point
// sampling, fixed steps) gives cones that rays do leave the solid in; the checker sees it.
void RelaxedConeMapTest::gpuGemsConesLeaveTheSolid() {
    long rays = 0, left = 0;
    double worst = 0;
    for (ProceduralMap map : {ProceduralMap::Noise, ProceduralMap::Random, ProceduralMap::Stones}) {
        const HeightField field = makeProceduralMap(map, 18, 18, 8);
        const ConeMap gems = test::bakeRelaxedConesGpuGems(field, 64);
        for (int y = 0; y < field.height; ++y) {
            for (int x = 0; x < field.width; ++x) {
                const test::ConeCheck check =
                    test::checkRelaxed(field, WrapMode::Repeat, x, y, gems.ratio(x, y), 1e-6);
                rays += check.points;
                left += check.violations;
                worst = std::max(worst, check.worst);
            }
        }
    }
    qInfo("GPU Gems 3 relaxed cones: %ld of %ld sampled in-cone rays left the solid, by up to %.4f",
          left, rays, worst);
    QVERIFY(left > 0);
    QVERIFY(worst > 1e-3);
}

QTEST_APPLESS_MAIN(RelaxedConeMapTest)
#include "RelaxedConeMapTest.moc"

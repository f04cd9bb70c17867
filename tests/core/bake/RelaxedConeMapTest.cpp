// Relaxed cone maps: the fast baker against the ring scan, wider than conservative cones, and the
// relaxed property on sampled rays, with the original GPU Gems 3 pre-process as a negative control.

#include "ConeChecks.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/ConeMapReference.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QtTest>
#include <cmath>

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

} // namespace

class RelaxedConeMapTest : public QObject {
    Q_OBJECT

private slots:
    void fastMatchesRingScan_data();
    void fastMatchesRingScan();
    void relaxedPropertyHolds();
    void gpuGemsConesLeaveTheSolid();
};

void RelaxedConeMapTest::fastMatchesRingScan_data() {
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("wrap");
    for (int i = 0; i < static_cast<int>(std::size(kCases)); ++i) {
        for (int w = 0; w < 2; ++w) {
            const QByteArray name = QByteArray::number(static_cast<int>(kCases[i].map)) + " " +
                                    QByteArray::number(kCases[i].width) + "x" +
                                    QByteArray::number(kCases[i].height) + " " +
                                    toString(WrapMode(w)).data();
            QTest::newRow(name.constData()) << i << w;
        }
    }
}

// The pyramid search finds the ring scan's cones (the per-cell bound's branch and bound stops at
// a 3% tolerance that depends on the order cells are met in, so the two agree to that), and
// relaxed cones are never narrower than the conservative ones (the oracle's within that 3%).
void RelaxedConeMapTest::fastMatchesRingScan() {
    QFETCH(int, index);
    QFETCH(int, wrap);
    const Case& k = kCases[index];
    const WrapMode mode = WrapMode(wrap);
    const HeightField field = makeProceduralMap(k.map, k.width, k.height, 5);
    Result<ConeMap> fast = bakeRelaxedConeMap(field, mode);
    QVERIFY(fast.ok());
    QCOMPARE(fast->kind, ConeKind::Relaxed);
    const ConeMap ring = bakeRelaxedConesBruteForce(field, mode);
    const ConeMap quick = *bakeQuickConeMap(field, mode);
    const ConeMap brute = bakeConservativeConesBruteForce(field, mode);
    int equal = 0;
    for (std::size_t i = 0; i < ring.sqrtRatio.size(); ++i) {
        const double f = fast->sqrtRatio[i], r = ring.sqrtRatio[i];
        QVERIFY2(std::abs(f * f - r * r) <= 0.03 * r * r,
                 qPrintable(QString("texel %1: %2 vs %3").arg(i).arg(f).arg(r)));
        equal += f == r;
        QVERIFY(fast->sqrtRatio[i] >= quick.sqrtRatio[i]);
        QVERIFY(f * f >=
                0.97 * brute.ratio(static_cast<int>(i % k.width), static_cast<int>(i / k.width)));
    }
    QVERIFY(equal >= static_cast<int>(ring.sqrtRatio.size()) * 95 / 100);
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

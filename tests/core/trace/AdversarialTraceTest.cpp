// Every ray, not a percentile: `cone`, `relaxed-cone` and `pyramid` at their defaults within 0.05
// texel of `exact` on maps made to break them, at grazing views, both wrap modes. The maps'
// random features come from seeds that change from run to run (printed with every failure;
// PX_TEST_SEED=N repeats one), so each run tries new maps.

#include "DoubleWalk.h"
#include "TestSupport.h"
#include "parallax/eval/HitErrorStats.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/TraceScene.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

using namespace px;

class AdversarialTraceTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void mapsFollowTheSeed();
    void everyRayKeepsItsBound_data();
    void everyRayKeepsItsBound();
    void capsThatBindStillEndExact();
    void exactMatchesADoubleWalk();
    void relaxedConeOnTheSamples();

private:
    unsigned m_seed = 1;
};

namespace {

struct Class {
    ProceduralMap map;
    int width, height;
};

constexpr Class kClasses[] = {
    {ProceduralMap::SpikeFlat, 128, 6}, {ProceduralMap::Walls, 32, 32},
    {ProceduralMap::Treads, 48, 16},    {ProceduralMap::Pits, 32, 32},
    {ProceduralMap::Terraces, 32, 32},  {ProceduralMap::Outliers, 32, 32},
    {ProceduralMap::Checker, 16, 16},   {ProceduralMap::Spikes, 32, 32},
    {ProceduralMap::Jpeg, 32, 32},
};

// The worst ray of `technique` against `exact` over the views, and every ray's error.
struct Worst {
    double error = 0.0;
    QString where;
    HitErrorAccumulator all;
};

Worst worstRay(const HeightField& field, WrapMode wrap, Technique technique,
               const TraceParams* params = nullptr) {
    auto exact = test::makeTracer(field, wrap, Technique::Exact, 0.1f);
    auto tracer = test::makeTracer(field, wrap, technique, 0.1f, params);
    Worst worst;
    if (!exact || !tracer) {
        worst.error = 1e30;
        worst.where = "no tracer";
        return worst;
    }
    for (double polar : {80.0, 87.0, 89.0}) {
        for (double azimuth : {0.0, 35.0, 45.0, 90.0, 200.0}) {
            TraceScene scene;
            scene.rays = 12;
            scene.polarDeg = polar;
            scene.azimuthDeg = azimuth;
            const auto a = traceScene(*exact, scene);
            const auto b = traceScene(*tracer, scene);
            worst.all.add(b, a, field.width, field.height);
            for (std::size_t k = 0; k < a.size(); ++k) {
                const double e = hitErrorTexels(a[k], b[k], field.width, field.height);
                if (!(e <= worst.error)) {
                    worst.error = e;
                    worst.where =
                        QString("polar %1, azimuth %2, ray %3").arg(polar).arg(azimuth).arg(k);
                }
            }
        }
    }
    return worst;
}

} // namespace

void AdversarialTraceTest::initTestCase() {
    const char* given = std::getenv("PX_TEST_SEED");
    m_seed = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                   : std::random_device{}() % 100000u;
    qInfo("adversarial map seeds %u to %u (PX_TEST_SEED=%u repeats them)", m_seed, m_seed + 1,
          m_seed);
}

// Each class is what it says, the same for the same seed and different for another.
void AdversarialTraceTest::mapsFollowTheSeed() {
    for (const Class& c : kClasses) {
        const char* name = proceduralMapNames()[static_cast<std::size_t>(c.map)].data();
        const HeightField a = makeProceduralMap(c.map, c.width, c.height, m_seed);
        QVERIFY2(a.texels == makeProceduralMap(c.map, c.width, c.height, m_seed).texels, name);
        // Another seed gives another map (a few seeds: 48 texels hold few sets of treads).
        bool differs = c.map == ProceduralMap::Checker;
        for (unsigned k = 1; k <= 8 && !differs; ++k)
            differs = a.texels != makeProceduralMap(c.map, c.width, c.height, m_seed + k).texels;
        QVERIFY2(differs, name);
        for (float h : a.texels)
            QVERIFY2(h >= 0.0f && h <= 1.0f, name);
    }
    const HeightField strip = makeProceduralMap(ProceduralMap::SpikeFlat, 128, 6, m_seed);
    for (int y = 0; y < strip.height; ++y) {
        int spikes = 0;
        for (int x = 0; x < strip.width; ++x)
            spikes += strip.at(x, y) == 1.0f;
        QCOMPARE(spikes, 1);
    }
    const HeightField terraces = makeProceduralMap(ProceduralMap::Terraces, 32, 32, m_seed);
    for (float h : terraces.texels)
        QVERIFY(std::abs(h * 255.0f - std::round(h * 255.0f)) < 1e-3f); // 8-bit levels
    const HeightField jpeg = makeProceduralMap(ProceduralMap::Jpeg, 32, 32, m_seed);
    for (float h : jpeg.texels)
        QVERIFY(std::abs(h * 255.0f - std::round(h * 255.0f)) < 1e-3f); // decoded 8 bits
    const HeightField pits = makeProceduralMap(ProceduralMap::Pits, 32, 32, m_seed);
    QVERIFY(std::count(pits.texels.begin(), pits.texels.end(), 0.0f) >= 1);
    QCOMPARE(std::count(pits.texels.begin(), pits.texels.end(), 0.0f) +
                 std::count(pits.texels.begin(), pits.texels.end(), 1.0f),
             static_cast<std::ptrdiff_t>(pits.texels.size()));
}

void AdversarialTraceTest::everyRayKeepsItsBound_data() {
    QTest::addColumn<int>("cls");
    QTest::addColumn<int>("wrap");
    QTest::addColumn<int>("technique");
    for (int c = 0; c < static_cast<int>(std::size(kClasses)); ++c) {
        for (int wrap = 0; wrap < 2; ++wrap) {
            for (Technique t : {Technique::Cone, Technique::RelaxedCone, Technique::Pyramid}) {
                const QByteArray name =
                    QByteArray(
                        proceduralMapNames()[static_cast<std::size_t>(kClasses[c].map)].data()) +
                    (wrap ? " clamp " : " repeat ") + info(t).name.data();
                QTest::newRow(name.constData()) << c << wrap << static_cast<int>(t);
            }
        }
    }
}

void AdversarialTraceTest::everyRayKeepsItsBound() {
    QFETCH(int, cls);
    QFETCH(int, wrap);
    QFETCH(int, technique);
    const Class& c = kClasses[cls];
    const Technique t = static_cast<Technique>(technique);
    for (unsigned seed : {m_seed, m_seed + 1}) {
        const HeightField field = makeProceduralMap(c.map, c.width, c.height, seed);
        const Worst w = worstRay(field, wrap ? WrapMode::Clamp : WrapMode::Repeat, t);
        QVERIFY(isDocumentedExact(t));
        QVERIFY2(w.error <= kExactTexels,
                 qPrintable(QString("seed %1: a ray %2 texels from exact at %3")
                                .arg(seed)
                                .arg(w.error)
                                .arg(w.where)));
    }
}

// Caps far too small for these rays: the march stops above the surface and the exact walk must
// take the ray to the same hit.
void AdversarialTraceTest::capsThatBindStillEndExact() {
    for (unsigned seed : {m_seed, m_seed + 1}) {
        const HeightField field = makeProceduralMap(ProceduralMap::SpikeFlat, 128, 6, seed);
        for (Technique t : {Technique::Cone, Technique::RelaxedCone, Technique::Pyramid}) {
            TraceParams params = info(t).defaults;
            params.maxSteps = 2;
            for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
                const Worst w = worstRay(field, wrap, t, &params);
                QVERIFY2(w.error <= kExactTexels,
                         qPrintable(QString("%1, seed %2, 2 steps: %3 texels off at %4")
                                        .arg(info(t).name.data())
                                        .arg(seed)
                                        .arg(w.error)
                                        .arg(w.where)));
            }
        }
    }
}

// The reference itself, against a float64 walk written apart from the kernels: on these maps at
// grazing views float32 `exact` finds the same hit on every ray.
void AdversarialTraceTest::exactMatchesADoubleWalk() {
    for (const Class& c : kClasses) {
        const HeightField field = makeProceduralMap(c.map, c.width, c.height, m_seed);
        for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
            auto exact = test::makeTracer(field, wrap, Technique::Exact, 0.1f);
            QVERIFY(exact.ok());
            for (double polar : {80.0, 89.0}) {
                for (double azimuth : {35.0, 90.0}) {
                    const glm::vec2 P = parallaxVector(0.1f, polar, azimuth);
                    for (int k = 0; k < 144; ++k) {
                        const int column = k % 12, row = k / 12;
                        const glm::dvec2 uv0((column + 0.5) / 12, (row + 0.5) / 12);
                        const TraceResult r = exact->trace(uv0, P);
                        const double t = test::doubleWalkT(field, wrap, uv0, glm::dvec2(P));
                        const double e = std::hypot((r.t - t) * P.x * field.width,
                                                    (r.t - t) * P.y * field.height);
                        QVERIFY2(e <= kExactTexels,
                                 qPrintable(
                                     QString("%1, seed %2, polar %3, azimuth %4, ray %5: "
                                             "float t %6, double t %7")
                                         .arg(proceduralMapNames()[static_cast<std::size_t>(c.map)]
                                                  .data())
                                         .arg(m_seed)
                                         .arg(polar)
                                         .arg(azimuth)
                                         .arg(k)
                                         .arg(r.t)
                                         .arg(t)));
                    }
                }
            }
        }
    }
}

// relaxed-cone on the built-in samples at every bench angle: every ray within 0.05 texel.
void AdversarialTraceTest::relaxedConeOnTheSamples() {
    for (double polar : {30.0, 60.0, 80.0, 87.0}) {
        HitErrorAccumulator acc;
        for (ProceduralMap m : {ProceduralMap::Bricks, ProceduralMap::Stones, ProceduralMap::Rivets,
                                ProceduralMap::Noise}) {
            const HeightField field = makeProceduralMap(m, 64, 64);
            auto exact = test::makeTracer(field, WrapMode::Repeat, Technique::Exact, 0.1f);
            auto relaxed = test::makeTracer(field, WrapMode::Repeat, Technique::RelaxedCone, 0.1f);
            QVERIFY(exact.ok() && relaxed.ok());
            TraceScene scene;
            scene.rays = 32;
            scene.polarDeg = polar;
            scene.azimuthDeg = 35;
            acc.add(traceScene(*relaxed, scene), traceScene(*exact, scene), 64, 64);
        }
        const HitErrorStats s = acc.stats();
        QVERIFY2(s.maxError <= kExactTexels,
                 qPrintable(QString("polar %1: a ray %2 texels from exact (p99 %3)")
                                .arg(polar)
                                .arg(s.maxError)
                                .arg(s.p99Error)));
    }
}

QTEST_APPLESS_MAIN(AdversarialTraceTest)
#include "AdversarialTraceTest.moc"

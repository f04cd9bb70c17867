// Stiff and extreme inputs: every technique returns finite hits with t in [0, 1] and fetches
// within its cap, whatever the map, angle or scale (docs/techniques.md, "How they fail").

#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/ParallaxBound.h"
#include "parallax/trace/TraceScene.h"

#include <QtTest>
#include <cmath>

using namespace px;

class StabilityTest : public QObject {
    Q_OBJECT

private slots:
    void extremeCases_data();
    void extremeCases();
    void scaleZeroCostsOneFetch();
    void farFromOriginKeepsPrecision();
    void nonFiniteParallaxIsBounded();
    void grazingParallaxKeepsItsDirection();
};

namespace {

struct Case {
    const char* name;
    ProceduralMap map;
    int width, height;
    float scale;
    double polar;
    double azimuth;
    glm::dvec2 offset;
};

const Case* s_cases = nullptr;

} // namespace

void StabilityTest::extremeCases_data() {
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("wrap");
    static const Case cases[] = {
        {"polar 89.9", ProceduralMap::Noise, 32, 32, 0.1f, 89.9, 35, {0, 0}},
        {"scale 10", ProceduralMap::Noise, 32, 32, 10.0f, 60, 35, {0, 0}},
        {"scale 10 grazing", ProceduralMap::Noise, 16, 16, 10.0f, 89.9, 10, {0, 0}},
        {"tiny scale", ProceduralMap::Noise, 32, 32, 1e-6f, 80, 35, {0, 0}},
        {"1x1", ProceduralMap::Random, 1, 1, 0.1f, 70, 35, {0, 0}},
        {"1xN", ProceduralMap::Random, 1, 37, 0.1f, 70, 80, {0, 0}},
        {"Nx1", ProceduralMap::Random, 29, 1, 0.1f, 70, 10, {0, 0}},
        {"checkerboard", ProceduralMap::Checker, 32, 32, 0.1f, 80, 35, {0, 0}},
        {"spikes", ProceduralMap::Spikes, 64, 64, 0.1f, 85, 35, {0, 0}},
        {"step", ProceduralMap::Step, 32, 32, 0.2f, 87, 0, {0, 0}},
        {"cracks", ProceduralMap::Cracks, 64, 64, 0.1f, 80, 0, {0, 0}},
        {"flat 0", ProceduralMap::Flat, 8, 8, 0.1f, 60, 35, {0, 0}},
        {"uv0 near 4096", ProceduralMap::Noise, 32, 32, 0.1f, 60, 35, {4096.0, 4095.0}},
        {"non power of two", ProceduralMap::Random, 23, 17, 0.3f, 85, 120, {0, 0}},
    };
    for (int wrap = 0; wrap < 2; ++wrap) {
        for (int i = 0; i < static_cast<int>(std::size(cases)); ++i) {
            const QByteArray name = QByteArray(cases[i].name) + (wrap ? " clamp" : " repeat");
            QTest::newRow(name.constData()) << i << wrap;
        }
    }
    s_cases = cases;
}

void StabilityTest::extremeCases() {
    QFETCH(int, index);
    QFETCH(int, wrap);
    const Case& c = s_cases[index];
    const WrapMode mode = wrap ? WrapMode::Clamp : WrapMode::Repeat;
    const HeightField field = makeProceduralMap(c.map, c.width, c.height, 5, 0.0f);
    TraceScene scene;
    scene.rays = 16;
    scene.polarDeg = c.polar;
    scene.azimuthDeg = c.azimuth;
    scene.uvOffset = c.offset;
    for (const TechniqueInfo& ti : allTechniques()) {
        auto tracer = test::makeTracer(field, mode, ti.id, c.scale);
        QVERIFY(tracer.ok());
        const long long cap =
            fetchCap(ti.id, ti.defaults,
                     rayCellBound(parallaxVector(c.scale, c.polar, c.azimuth), c.width, c.height));
        for (const TraceResult& r : traceScene(*tracer, scene)) {
            QVERIFY2(std::isfinite(r.u) && std::isfinite(r.v) && std::isfinite(r.t),
                     ti.name.data());
            QVERIFY2(r.t >= 0.0f && r.t <= 1.0f, ti.name.data());
            QVERIFY2(
                r.fetches >= 0 && r.fetches <= cap,
                qPrintable(
                    QString("%1: %2 fetches, cap %3").arg(ti.name.data()).arg(r.fetches).arg(cap)));
        }
    }
}

void StabilityTest::scaleZeroCostsOneFetch() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 16, 16);
    for (const TechniqueInfo& ti : allTechniques()) {
        auto tracer = test::makeTracer(field, WrapMode::Repeat, ti.id, 0.0f);
        QVERIFY(tracer.ok());
        const TraceResult r = tracer->trace({0.3, 0.6}, parallaxVector(0.0f, 80, 35));
        QCOMPARE(r.fetches, ti.parallax ? 1 : 0);
        QCOMPARE(r.u, 0.3);
        QCOMPARE(r.v, 0.6);
    }
}

// uv0 = 4096.3 in float is 4096.2998: a texel of 1024 is 0.00098, so the hit must still agree with
// the same ray traced at 0.3 to well under a texel.
void StabilityTest::farFromOriginKeepsPrecision() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 1024, 1024);
    auto tracer = test::makeTracer(field, WrapMode::Repeat, Technique::Pyramid, 0.05f);
    QVERIFY(tracer.ok());
    const glm::vec2 P = parallaxVector(0.05f, 70, 35);
    const TraceResult nearOrigin = tracer->trace({0.3, 0.7}, P);
    const TraceResult far = tracer->trace({4096.3, 4095.7}, P);
    QVERIFY(std::abs((far.u - 4096.0) - nearOrigin.u) * 1024 < 0.01);
    QVERIFY(std::abs((far.v - 4095.0) - nearOrigin.v) * 1024 < 0.01);
    QCOMPARE(far.fetches, nearOrigin.fetches);
}

void StabilityTest::nonFiniteParallaxIsBounded() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 16, 16);
    for (const TechniqueInfo& ti : allTechniques()) {
        auto tracer = test::makeTracer(field, WrapMode::Repeat, ti.id, 0.1f);
        QVERIFY(tracer.ok());
        for (glm::vec2 P : {glm::vec2(std::nanf(""), 0.0f), glm::vec2(INFINITY, -INFINITY),
                            glm::vec2(1e30f, 1e-30f)}) {
            const TraceResult r = tracer->trace({0.5, 0.5}, P);
            QVERIFY2(std::isfinite(r.u) && std::isfinite(r.v) && r.t >= 0 && r.t <= 1,
                     ti.name.data());
        }
    }
}

// Scale 100 at 89.99 degrees asks for |P| = 5.7e5 uv: the bound shortens it to 1e4 along the same
// azimuth (35 degrees, not the 45 a per-component clamp made of it) and says so.
void StabilityTest::grazingParallaxKeepsItsDirection() {
    const glm::vec2 P = parallaxVector(100.0f, 89.99, 35);
    const BoundedParallax b = boundParallax(P);
    QVERIFY(!b.note.empty());
    QVERIFY2(b.note.find("5.73e+05") != std::string::npos, b.note.c_str());
    QVERIFY(std::abs(std::hypot(b.P.x, b.P.y) - 1.0e4) < 1.0);
    QVERIFY(std::abs(std::atan2(b.P.y, b.P.x) * 180.0 / 3.14159265358979 - 35.0) < 1e-4);
    QVERIFY(boundParallax(parallaxVector(0.1f, 80, 35)).note.empty());
    QCOMPARE(boundParallax(glm::vec2(3.0f, -4.0f)).P, glm::vec2(3.0f, -4.0f));
    // An infinite component keeps its sign's direction.
    const glm::vec2 inf = boundParallax(glm::vec2(-INFINITY, 2.0f)).P;
    QCOMPARE(inf, glm::vec2(-1.0e4f, 0.0f));
    // The tracers use the bounded vector: the hit moves along the view's azimuth.
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 16, 16);
    auto tracer = test::makeTracer(field, WrapMode::Repeat, Technique::Pyramid, 100.0f);
    QVERIFY(tracer.ok());
    const TraceResult r = tracer->trace({0.5, 0.5}, P);
    QVERIFY(r.t > 0.0f);
    QVERIFY(std::abs(std::atan2(r.v - 0.5, r.u - 0.5) * 180.0 / 3.14159265358979 - 35.0) < 1e-3);
}

QTEST_APPLESS_MAIN(StabilityTest)
#include "StabilityTest.moc"

// `exact` against an independent oracle (a dense double-precision march) and closed forms.

#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/TraceScene.h"

#include <QtTest>
#include <cmath>

using namespace px;

class ExactTraceTest : public QObject {
    Q_OBJECT

private slots:
    void agreesWithDenseMarch_data();
    void agreesWithDenseMarch();
    void flatMaps();
    void linearRamp();
    void singleStep();
    void hitIsOnTheSurface();
};

void ExactTraceTest::agreesWithDenseMarch_data() {
    QTest::addColumn<double>("polar");
    QTest::addColumn<double>("azimuth");
    QTest::addColumn<int>("wrap");
    for (int wrap = 0; wrap < 2; ++wrap) {
        for (double polar : {0.0, 45.0, 89.0}) {
            for (double azimuth : {0.0, 90.0, 180.0, 270.0, 45.0, 35.0, 225.0}) {
                const QByteArray name = QByteArray(wrap ? "clamp" : "repeat") + " polar " +
                                        QByteArray::number(polar) + " azimuth " +
                                        QByteArray::number(azimuth);
                QTest::newRow(name.constData()) << polar << azimuth << wrap;
            }
        }
    }
}

void ExactTraceTest::agreesWithDenseMarch() {
    QFETCH(double, polar);
    QFETCH(double, azimuth);
    QFETCH(int, wrap);
    const WrapMode mode = wrap ? WrapMode::Clamp : WrapMode::Repeat;
    const HeightField field = makeProceduralMap(ProceduralMap::Random, 13, 11, 7);
    const float scale = 0.05f;
    auto tracer = test::makeTracer(field, mode, Technique::Exact, scale);
    QVERIFY(tracer.ok());

    TraceScene scene;
    scene.rays = 20;
    scene.polarDeg = polar;
    scene.azimuthDeg = azimuth;
    const glm::vec2 P = parallaxVector(scale, polar, azimuth);
    const double cells = std::abs(P.x) * field.width + std::abs(P.y) * field.height;
    const int samples = std::max(4000, static_cast<int>(cells * 2000));
    int tangent = 0;
    for (int j = 0; j < scene.rays; ++j) {
        for (int i = 0; i < scene.rays; ++i) {
            const glm::dvec2 uv0 = rayOrigin(scene, i, j);
            const TraceResult r = tracer->trace(uv0, P);
            const double oracle = test::denseMarchT(field, mode, uv0.x, uv0.y, P.x, P.y, samples);
            if (std::abs(r.t - oracle) <= 1e-5)
                continue;
            // A disagreement is allowed only where the oracle's march stepped over a grazing
            // touch the exact solve found: the exact hit must lie on the surface, above the
            // oracle's hit, with the ray no deeper than a hair in between.
            const double fAtExact =
                test::bilinearHeight(field, mode, uv0.x + P.x * r.t, uv0.y + P.y * r.t) - (1 - r.t);
            QVERIFY2(r.t < oracle && std::abs(fAtExact) < 1e-5,
                     qPrintable(QString("ray %1,%2: exact t %3, dense march t %4")
                                    .arg(i)
                                    .arg(j)
                                    .arg(r.t, 0, 'g', 9)
                                    .arg(oracle, 0, 'g', 9)));
            ++tangent;
        }
    }
    QVERIFY2(tangent <= 2, qPrintable(QString("%1 grazing disagreements").arg(tangent)));
}

void ExactTraceTest::flatMaps() {
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        const HeightField low = makeProceduralMap(ProceduralMap::Flat, 8, 8, 1, 0.0f);
        const HeightField high = makeProceduralMap(ProceduralMap::Flat, 8, 8, 1, 1.0f);
        auto bottom = test::makeTracer(low, mode, Technique::Exact, 0.1f);
        auto top = test::makeTracer(high, mode, Technique::Exact, 0.1f);
        QVERIFY(bottom.ok() && top.ok());
        const glm::vec2 P = parallaxVector(0.1f, 60.0, 35.0);
        const TraceResult b = bottom->trace({0.3, 0.7}, P);
        QCOMPARE(b.t, 1.0f);
        QVERIFY(std::abs(b.u - (0.3 + P.x)) < 1e-6 && std::abs(b.v - (0.7 + P.y)) < 1e-6);
        const TraceResult t = top->trace({0.3, 0.7}, P);
        QCOMPARE(t.t, 0.0f);
        QCOMPARE(t.u, 0.3);
        QCOMPARE(t.v, 0.7);
    }
}

// h = (X)/(W-1) between the first and last texel centres (clamp): the hit has a closed form.
void ExactTraceTest::linearRamp() {
    const int W = 32;
    const HeightField ramp = makeProceduralMap(ProceduralMap::Ramp, W, 4);
    for (Technique technique : {Technique::Exact, Technique::Pyramid, Technique::Pom,
                                Technique::Secant, Technique::Cone}) {
        auto tracer = test::makeTracer(ramp, WrapMode::Clamp, technique, 0.1f);
        QVERIFY(tracer.ok());
        for (double azimuth : {0.0, 180.0, 30.0}) {
            const glm::vec2 P = parallaxVector(0.1f, 50.0, azimuth);
            const double u0 = 0.55;
            const double expected = (1.0 - (W * u0 - 0.5) / (W - 1)) / (1.0 + W * P.x / (W - 1));
            const TraceResult r = tracer->trace({u0, 0.5}, P);
            QVERIFY2(std::abs(r.t - expected) < 2e-5,
                     qPrintable(QString("%1 azimuth %2: t %3, expected %4")
                                    .arg(QString::fromUtf8(info(technique).name.data()))
                                    .arg(azimuth)
                                    .arg(r.t, 0, 'g', 9)
                                    .arg(expected, 0, 'g', 9)));
        }
    }
}

// A vertical step: 0 left of the middle, 1 right of it; the bilinear wall rises over one cell.
void ExactTraceTest::singleStep() {
    const int W = 16;
    const HeightField step = makeProceduralMap(ProceduralMap::Step, W, 4);
    auto tracer = test::makeTracer(step, WrapMode::Clamp, Technique::Exact, 0.2f);
    QVERIFY(tracer.ok());
    const glm::vec2 P = parallaxVector(0.2f, 70.0, 0.0);
    const double c = W / 2.0 - 1.0; // the wall cell (W is even), in cell coordinates
    for (double u0 : {0.05, 0.15, 0.25, 0.4}) {
        const double X0 = u0 * W - 0.5, dX = P.x * W;
        double expected = (1.0 - X0 + c) / (1.0 + dX); // on the wall: t = 1 - (X - c)
        if (X0 + dX * expected < c)
            expected = 1.0; // reaches the floor first
        if (X0 >= c + 1)
            expected = 0.0;
        const TraceResult r = tracer->trace({u0, 0.5}, P);
        QVERIFY2(std::abs(r.t - expected) < 1e-5,
                 qPrintable(QString("u0 %1: t %2, expected %3").arg(u0).arg(r.t).arg(expected)));
    }
}

void ExactTraceTest::hitIsOnTheSurface() {
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 64, 64);
    auto tracer = test::makeTracer(field, WrapMode::Repeat, Technique::Exact, 0.08f);
    QVERIFY(tracer.ok());
    const glm::vec2 P = parallaxVector(0.08f, 75.0, 200.0);
    for (int k = 0; k < 200; ++k) {
        const glm::dvec2 uv0((k * 37 % 200) / 200.0, (k * 91 % 200) / 200.0);
        const TraceResult r = tracer->trace(uv0, P);
        const double h = test::bilinearHeight(field, WrapMode::Repeat, r.u, r.v);
        QVERIFY(r.t >= 0.0f && r.t <= 1.0f);
        QVERIFY2(r.t == 1.0f || std::abs(h - (1.0 - r.t)) < 2e-5,
                 qPrintable(QString("h %1 vs depth %2").arg(h).arg(1.0 - r.t)));
    }
}

QTEST_APPLESS_MAIN(ExactTraceTest)
#include "ExactTraceTest.moc"

// Float32 `exact` on the longest rays the tracers accept (height scale 100, polar 89° to 89.99°:
// |P| at or near its bound of 10^4 uv, hundreds of thousands of cells) against the float64 walk of
// tests/support/DoubleWalk.h, on noise and on the adversarial maps, several seeds.

#include "DoubleWalk.h"
#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/TraceScene.h"
#include "trace/TraceKernel.h"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace px;

class LongRayTraceTest : public QObject {
    Q_OBJECT

private slots:
    void exactMatchesADoubleWalk_data();
    void exactMatchesADoubleWalk();
};

namespace {

struct Class {
    ProceduralMap map;
    int width, height;
};

constexpr Class kClasses[] = {
    {ProceduralMap::Noise, 32, 32},    {ProceduralMap::SpikeFlat, 128, 6},
    {ProceduralMap::Walls, 32, 32},    {ProceduralMap::Treads, 48, 16},
    {ProceduralMap::Pits, 32, 32},     {ProceduralMap::Terraces, 32, 32},
    {ProceduralMap::Outliers, 32, 32}, {ProceduralMap::Spikes, 32, 32},
};

// The parallax vector the tracer walks: the view's, bounded as the kernels bound it.
glm::vec2 boundedParallax(float scale, double polar, double azimuth) {
    kernel::TraceKernel k;
    return k.pxBoundParallax(parallaxVector(scale, polar, azimuth));
}

} // namespace

void LongRayTraceTest::exactMatchesADoubleWalk_data() {
    QTest::addColumn<double>("polar");
    for (double polar : {89.0, 89.9, 89.99})
        QTest::newRow(QByteArray::number(polar).constData()) << polar;
}

void LongRayTraceTest::exactMatchesADoubleWalk() {
    QFETCH(double, polar);
    const float scale =
        qEnvironmentVariableIsSet("PX_SCALE") ? qEnvironmentVariable("PX_SCALE").toFloat() : 100.0f;
    int over = 0, outsideCount = 0;
    double worstOutside = 0.0;
    const float kEps = std::ldexp(1.0f, -22);
    double worst = 0.0;
    QString where;
    int rays = 0;
    for (const Class& c : kClasses) {
        for (unsigned seed : {1u, 2u, 3u}) {
            const HeightField field = makeProceduralMap(c.map, c.width, c.height, seed);
            HeightField raised = field, lowered = field;
            for (float& h : raised.texels)
                h += kEps;
            for (float& h : lowered.texels)
                h -= kEps;
            for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
                auto exact = test::makeTracer(field, wrap, Technique::Exact, scale);
                QVERIFY(exact.ok());
                for (double azimuth : {35.0, 90.0, 200.0}) {
                    const glm::vec2 view = parallaxVector(scale, polar, azimuth);
                    const glm::vec2 P = boundedParallax(scale, polar, azimuth);
                    for (int k = 0; k < 16; ++k) {
                        const glm::dvec2 uv0((k % 4 + 0.5) / 4, (k / 4 + 0.5) / 4);
                        const TraceResult r = exact->trace(uv0, view);
                        const double t = test::doubleWalkT(field, wrap, uv0, glm::dvec2(P));
                        const double tHigh = test::doubleWalkT(raised, wrap, uv0, glm::dvec2(P));
                        const double tLow = test::doubleWalkT(lowered, wrap, uv0, glm::dvec2(P));
                        const double texelsPerT = std::hypot(P.x * field.width, P.y * field.height);
                        const double outside =
                            std::max({0.0, tHigh - r.t, r.t - tLow}) * texelsPerT;
                        worstOutside = std::max(worstOutside, outside);
                        outsideCount += outside > 0.05;
                        const double e = std::hypot((r.t - t) * P.x * field.width,
                                                    (r.t - t) * P.y * field.height);
                        ++rays;
                        over += e > 0.05;
                        if (!(e <= worst)) {
                            worst = e;
                            where = QString("%1 seed %2 %3 azimuth %4 ray %5: float t %6, "
                                            "double t %7")
                                        .arg(proceduralMapNames()[static_cast<std::size_t>(c.map)]
                                                 .data())
                                        .arg(seed)
                                        .arg(wrap == WrapMode::Repeat ? "repeat" : "clamp")
                                        .arg(azimuth)
                                        .arg(k)
                                        .arg(r.t, 0, 'g', 9)
                                        .arg(t, 0, 'g', 12);
                        }
                    }
                }
            }
        }
    }
    qInfo("outside the +-eps band: %d rays, worst %g texels", outsideCount, worstOutside);
    qInfo("scale %g polar %g: %d rays, %d over 0.05, worst %g texels (%s)", scale, polar, rays,
          over, worst, qPrintable(where));
}

QTEST_APPLESS_MAIN(LongRayTraceTest)
#include "LongRayTraceTest.moc"

// `pyramid` finds the same hit as `exact` (within 0.01 texel) while reading far fewer cells.

#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/TraceScene.h"

#include <QtTest>

using namespace px;

class PyramidTraceTest : public QObject {
    Q_OBJECT

private slots:
    void matchesExact_data();
    void matchesExact();
    void boundaryRays();
    void visitsFewerCells();
};

void PyramidTraceTest::matchesExact_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addColumn<int>("wrap");
    for (int wrap = 0; wrap < 2; ++wrap) {
        const char* mode = wrap ? "clamp" : "repeat";
        QTest::newRow(QByteArray(mode).append(" 32x32").constData()) << 32 << 32 << wrap;
        QTest::newRow(QByteArray(mode).append(" 23x17").constData()) << 23 << 17 << wrap;
        QTest::newRow(QByteArray(mode).append(" 1x1").constData()) << 1 << 1 << wrap;
        QTest::newRow(QByteArray(mode).append(" 1x9").constData()) << 1 << 9 << wrap;
        QTest::newRow(QByteArray(mode).append(" 40x3").constData()) << 40 << 3 << wrap;
    }
}

void PyramidTraceTest::matchesExact() {
    QFETCH(int, width);
    QFETCH(int, height);
    QFETCH(int, wrap);
    const WrapMode mode = wrap ? WrapMode::Clamp : WrapMode::Repeat;
    const HeightField field = makeProceduralMap(ProceduralMap::Random, width, height, 11);
    for (float scale : {0.05f, 0.3f}) {
        auto exact = test::makeTracer(field, mode, Technique::Exact, scale);
        auto pyramid = test::makeTracer(field, mode, Technique::Pyramid, scale);
        QVERIFY(exact.ok() && pyramid.ok());
        for (double polar : {0.0, 10.0, 30.0, 45.0, 60.0, 75.0, 80.0, 85.0, 87.0, 89.0}) {
            for (double azimuth : {0.0, 35.0, 90.0, 135.0, 180.0, 200.0, 270.0, 315.0}) {
                TraceScene scene;
                scene.rays = 12;
                scene.polarDeg = polar;
                scene.azimuthDeg = azimuth;
                const auto a = traceScene(*exact, scene);
                const auto b = traceScene(*pyramid, scene);
                for (std::size_t k = 0; k < a.size(); ++k) {
                    const double error = hitErrorTexels(a[k], b[k], width, height);
                    QVERIFY2(error <= 0.01,
                             qPrintable(QString("scale %1 polar %2 azimuth %3 ray %4: %5 texels "
                                                "(t %6 vs %7)")
                                            .arg(scale)
                                            .arg(polar)
                                            .arg(azimuth)
                                            .arg(k)
                                            .arg(error)
                                            .arg(a[k].t)
                                            .arg(b[k].t)));
                }
            }
        }
    }
}

// Rays that start exactly on cell and node borders, and move along them.
void PyramidTraceTest::boundaryRays() {
    const HeightField field = makeProceduralMap(ProceduralMap::Random, 16, 16, 3);
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        auto exact = test::makeTracer(field, mode, Technique::Exact, 0.2f);
        auto pyramid = test::makeTracer(field, mode, Technique::Pyramid, 0.2f);
        QVERIFY(exact.ok() && pyramid.ok());
        for (double u : {0.0, 0.5 / 16, 1.0 / 16, 0.5, 8.5 / 16, 1.0}) {
            for (glm::vec2 P :
                 {glm::vec2(0.3f, 0.0f), glm::vec2(0.0f, -0.3f), glm::vec2(-0.5f, 0.0f),
                  glm::vec2(0.25f, 0.25f), glm::vec2(-1.0f, 2.0f)}) {
                const TraceResult a = exact->trace({u, 0.5 / 16}, P);
                const TraceResult b = pyramid->trace({u, 0.5 / 16}, P);
                QVERIFY2(hitErrorTexels(a, b, 16, 16) <= 0.01,
                         qPrintable(QString("u %1 P (%2, %3): t %4 vs %5")
                                        .arg(u)
                                        .arg(P.x)
                                        .arg(P.y)
                                        .arg(a.t)
                                        .arg(b.t)));
            }
        }
    }
}

void PyramidTraceTest::visitsFewerCells() {
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 256, 256);
    auto exact = test::makeTracer(field, WrapMode::Repeat, Technique::Exact, 0.1f);
    auto pyramid = test::makeTracer(field, WrapMode::Repeat, Technique::Pyramid, 0.1f);
    QVERIFY(exact.ok() && pyramid.ok());
    TraceScene scene;
    scene.rays = 32;
    scene.polarDeg = 87;
    scene.azimuthDeg = 35;
    long long exactFetches = 0, pyramidFetches = 0;
    for (const TraceResult& r : traceScene(*exact, scene))
        exactFetches += r.fetches;
    for (const TraceResult& r : traceScene(*pyramid, scene))
        pyramidFetches += r.fetches;
    QVERIFY2(
        pyramidFetches * 2 < exactFetches,
        qPrintable(QString("pyramid %1 fetches, exact %2").arg(pyramidFetches).arg(exactFetches)));
}

QTEST_APPLESS_MAIN(PyramidTraceTest)
#include "PyramidTraceTest.moc"

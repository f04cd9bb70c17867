// `cone` and `relaxed-cone` against `exact`, with cone maps baked in memory.

#include "TestSupport.h"
#include "parallax/bake/ConeMapReference.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/TraceScene.h"

#include <QtTest>
#include <algorithm>

using namespace px;

class ConeTraceTest : public QObject {
    Q_OBJECT

private slots:
    void coneIsNearlyExact_data();
    void coneIsNearlyExact();
    void relaxedConeIsClose();
    void zeroConesDoNotStall();
};

void ConeTraceTest::coneIsNearlyExact_data() {
    QTest::addColumn<int>("map");
    QTest::addColumn<int>("wrap");
    for (ProceduralMap m : {ProceduralMap::Noise, ProceduralMap::Random, ProceduralMap::Spikes}) {
        for (int wrap = 0; wrap < 2; ++wrap) {
            const QByteArray name =
                QByteArray::number(static_cast<int>(m)) + (wrap ? " clamp" : " repeat");
            QTest::newRow(name.constData()) << static_cast<int>(m) << wrap;
        }
    }
}

// Conservative cones never step past the surface, and every short step ends in an exact cell
// solve: with an ample step cap the hit is the exact one.
void ConeTraceTest::coneIsNearlyExact() {
    QFETCH(int, map);
    QFETCH(int, wrap);
    const WrapMode mode = wrap ? WrapMode::Clamp : WrapMode::Repeat;
    const HeightField field = makeProceduralMap(static_cast<ProceduralMap>(map), 24, 24, 9);
    TraceParams params = info(Technique::Cone).defaults;
    params.maxSteps = 4096;
    for (double polar : {30.0, 60.0, 80.0, 87.0}) {
        auto exact = test::makeTracer(field, mode, Technique::Exact, 0.1f);
        auto cone = test::makeTracer(field, mode, Technique::Cone, 0.1f, &params);
        QVERIFY(exact.ok() && cone.ok());
        TraceScene scene;
        scene.rays = 24;
        scene.polarDeg = polar;
        scene.azimuthDeg = 35;
        const auto a = traceScene(*exact, scene);
        const auto b = traceScene(*cone, scene);
        int far = 0;
        for (std::size_t k = 0; k < a.size(); ++k)
            far += hitErrorTexels(a[k], b[k], 24, 24) > 0.01;
        QVERIFY2(far == 0, qPrintable(QString("polar %1: %2 rays off").arg(polar).arg(far)));
    }
}

void ConeTraceTest::relaxedConeIsClose() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 32, 32, 4);
    auto exact = test::makeTracer(field, WrapMode::Repeat, Technique::Exact, 0.1f);
    auto relaxed = test::makeTracer(field, WrapMode::Repeat, Technique::RelaxedCone, 0.1f);
    QVERIFY(exact.ok() && relaxed.ok());
    TraceScene scene;
    scene.rays = 32;
    scene.polarDeg = 60;
    scene.azimuthDeg = 35;
    const auto a = traceScene(*exact, scene);
    const auto b = traceScene(*relaxed, scene);
    std::vector<double> errors;
    for (std::size_t k = 0; k < a.size(); ++k)
        errors.push_back(hitErrorTexels(a[k], b[k], 32, 32));
    std::sort(errors.begin(), errors.end());
    const double p99 = errors[errors.size() * 99 / 100];
    QVERIFY2(p99 < 1.0, qPrintable(QString("p99 %1 texels").arg(p99)));
}

// A cone map of zeros would stall a plain cone march; the cell-exit minimum step keeps it going
// and the cell solves keep it exact.
void ConeTraceTest::zeroConesDoNotStall() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 16, 16, 2);
    ConeMap zeros(ConeKind::Conservative, 16, 16);
    std::fill(zeros.sqrtRatio.begin(), zeros.sqrtRatio.end(), 0.0f);
    TraceMaps maps;
    maps.height = &field;
    maps.cone = &zeros;
    TraceParams params = info(Technique::Cone).defaults;
    params.maxSteps = 256;
    auto cone = Tracer::create(maps, Technique::Cone, params, 0.1f);
    auto exact = test::makeTracer(field, WrapMode::Repeat, Technique::Exact, 0.1f);
    QVERIFY(cone.ok() && exact.ok());
    const glm::vec2 P = parallaxVector(0.1f, 70, 35);
    for (int k = 0; k < 50; ++k) {
        const glm::dvec2 uv0(k / 50.0, (k * 7 % 50) / 50.0);
        const TraceResult a = exact->trace(uv0, P), b = cone->trace(uv0, P);
        QVERIFY(hitErrorTexels(a, b, 16, 16) < 0.01);
    }
}

QTEST_APPLESS_MAIN(ConeTraceTest)
#include "ConeTraceTest.moc"

// More layers or refinement steps never make the marching techniques' mean error worse.

#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/TraceScene.h"

#include <QtTest>
#include <glm/geometric.hpp>
#include <optional>

using namespace px;

class ConvergenceTest : public QObject {
    Q_OBJECT

private slots:
    void moreLayersNeverWorse_data();
    void moreLayersNeverWorse();
    void moreRefinementNeverWorse_data();
    void moreRefinementNeverWorse();
};

namespace {

// The mean error, or nothing when the tracer could not be created (which fails the test).
std::optional<double> meanError(const HeightField& field, Technique technique,
                                const TraceParams& params,
                                const std::vector<TraceResult>& reference, const TraceScene& scene,
                                float scale) {
    auto tracer = test::makeTracer(field, WrapMode::Repeat, technique, scale, &params);
    if (!tracer)
        return std::nullopt;
    const auto results = traceScene(*tracer, scene);
    double sum = 0;
    for (std::size_t k = 0; k < results.size(); ++k)
        sum += hitErrorTexels(results[k], reference[k], field.width, field.height);
    return sum / results.size();
}

void addCases(std::initializer_list<Technique> techniques) {
    QTest::addColumn<int>("technique");
    QTest::addColumn<int>("map");
    QTest::addColumn<double>("polar");
    for (Technique t : techniques) {
        for (ProceduralMap m : {ProceduralMap::Noise, ProceduralMap::Bricks}) {
            for (double polar : {30.0, 60.0, 80.0}) {
                const QByteArray name = QByteArray(info(t).name.data()) + " map " +
                                        QByteArray::number(static_cast<int>(m)) + " polar " +
                                        QByteArray::number(polar);
                QTest::newRow(name.constData())
                    << static_cast<int>(t) << static_cast<int>(m) << polar;
            }
        }
    }
}

} // namespace

void ConvergenceTest::moreLayersNeverWorse_data() {
    addCases({Technique::Steep, Technique::Pom, Technique::Relief, Technique::Secant});
}

void ConvergenceTest::moreLayersNeverWorse() {
    QFETCH(int, technique);
    QFETCH(int, map);
    QFETCH(double, polar);
    const HeightField field = makeProceduralMap(static_cast<ProceduralMap>(map), 64, 64);
    const float scale = 0.08f;
    TraceScene scene;
    scene.rays = 48;
    scene.polarDeg = polar;
    scene.azimuthDeg = 35;
    auto exact = test::makeTracer(field, WrapMode::Repeat, Technique::Exact, scale);
    QVERIFY(exact.ok());
    const auto reference = traceScene(*exact, scene);

    const Technique t = static_cast<Technique>(technique);
    double previous = 1e30;
    for (int layers = 4; layers <= 256; layers *= 2) {
        TraceParams params = info(t).defaults;
        params.minLayers = params.maxLayers = layers;
        const std::optional<double> measured = meanError(field, t, params, reference, scene, scale);
        QVERIFY2(measured, "no tracer for these parameters");
        const double error = *measured;
        // 1e-5 texel: float rounding once the error has converged.
        QVERIFY2(
            error <= previous + 1e-5,
            qPrintable(
                QString("%1 layers: mean error %2 > %3").arg(layers).arg(error).arg(previous)));
        previous = error;
    }
    // At worst one layer's travel: |P| W / layers texels.
    const glm::vec2 P = parallaxVector(scale, polar, 35);
    const double layerTexels = glm::length(P) * field.width / 256;
    QVERIFY2(previous <= layerTexels,
             qPrintable(QString("256 layers still err by %1 texels").arg(previous)));
}

void ConvergenceTest::moreRefinementNeverWorse_data() {
    addCases({Technique::Relief, Technique::Secant});
}

void ConvergenceTest::moreRefinementNeverWorse() {
    QFETCH(int, technique);
    QFETCH(int, map);
    QFETCH(double, polar);
    const Technique t = static_cast<Technique>(technique);
    const HeightField field = makeProceduralMap(static_cast<ProceduralMap>(map), 64, 64);
    const float scale = 0.08f;
    TraceScene scene;
    scene.rays = 48;
    scene.polarDeg = polar;
    scene.azimuthDeg = 35;
    auto exact = test::makeTracer(field, WrapMode::Repeat, Technique::Exact, scale);
    QVERIFY(exact.ok());
    const auto reference = traceScene(*exact, scene);
    double previous = 1e30;
    for (int steps = 0; steps <= 10; ++steps) {
        TraceParams params = info(t).defaults;
        params.binarySteps = params.secantSteps = steps;
        const std::optional<double> measured = meanError(field, t, params, reference, scene, scale);
        QVERIFY2(measured, "no tracer for these parameters");
        const double error = *measured;
        QVERIFY2(error <= previous + 1e-5,
                 qPrintable(
                     QString("%1 steps: mean error %2 > %3").arg(steps).arg(error).arg(previous)));
        previous = error;
    }
}

QTEST_APPLESS_MAIN(ConvergenceTest)
#include "ConvergenceTest.moc"

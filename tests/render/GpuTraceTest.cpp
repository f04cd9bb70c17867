// GPU == CPU: the canonical trace scene on the GPU (the shaders/trace kernels compiled as GLSL)
// against the CPU Tracer (the same kernels compiled as C++), every technique, both wrap modes,
// straight-down to grazing views, far-from-origin tiles: hit uv within 1e-3 texel, same fetches.
// llvmpipe evaluates the verify kernels as the CPU does, to the bit; a real GPU's compiler may
// round a loop's test otherwise (an H100 took one fetch fewer on a cone ray at 89 degrees, same
// hit), so there fetch counts may differ by a fetch or two on at most 0.5% of the rays.

#include "RenderTestSupport.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/eval/HitErrorStats.h"
#include "parallax/render/GpuTracer.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QtTest>
#include <algorithm>

using namespace px;

class GpuTraceTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(test::glContext()); }
    void gpuEqualsCpu_data();
    void gpuEqualsCpu();
    void coneOnAFoundLongRay();
    void bakesWhatTheTechniqueReadsWhenNotGiven();
    void refusesWhatTheCpuRefuses();
};

void GpuTraceTest::gpuEqualsCpu_data() {
    QTest::addColumn<int>("map");
    QTest::addColumn<int>("wrap");
    for (int wrap = 0; wrap < 2; ++wrap) {
        const char* w = wrap ? "clamp" : "repeat";
        QTest::newRow(QByteArray("random 23x17 ").append(w).constData()) << 0 << wrap;
        QTest::newRow(QByteArray("noise 32x32 ").append(w).constData()) << 1 << wrap;
    }
}

void GpuTraceTest::gpuEqualsCpu() {
    QFETCH(int, map);
    QFETCH(int, wrap);
    const HeightField field = map == 0 ? makeProceduralMap(ProceduralMap::Random, 23, 17, 7)
                                       : makeProceduralMap(ProceduralMap::Noise, 32, 32, 3);
    TraceMaps maps;
    maps.height = &field;
    maps.wrap = wrap ? WrapMode::Clamp : WrapMode::Repeat;
    const ConeMap cone = bakeConeMap(field, maps.wrap, ConeKind::Conservative);
    const ConeMap relaxed = bakeConeMap(field, maps.wrap, ConeKind::Relaxed);
    const MaxMipPyramid pyramid = MaxMipPyramid::build(field, maps.wrap);
    maps.cone = &cone;
    maps.relaxedCone = &relaxed;
    maps.pyramid = &pyramid;

    ShaderCache shaders;
    const bool bitExact = test::isLlvmpipe(test::glContext()->info().renderer);
    long long rays = 0, fetchesDiffer = 0;
    double worst = 0.0;
    for (const TechniqueInfo& technique : allTechniques()) {
        for (float scale : {0.0f, 0.05f, 0.3f}) {
            for (double polar : {0.0, 30.0, 60.0, 85.0, 89.0}) {
                for (double azimuth : {0.0, 35.0, 90.0, 200.0}) {
                    if (scale == 0.0f && (polar != 60.0 || azimuth != 35.0))
                        continue;
                    TraceScene scene;
                    scene.rays = 12;
                    scene.polarDeg = polar;
                    scene.azimuthDeg = azimuth;
                    if (!wrap && azimuth == 200.0)
                        scene.uvOffset = {4096.3, -17.6}; // far tiles: the tile is set aside first
                    Result<Tracer> cpu =
                        Tracer::create(maps, technique.id, technique.defaults, scale);
                    QVERIFY(cpu.ok());
                    const std::vector<TraceResult> expected = traceScene(*cpu, scene);
                    Result<std::vector<TraceResult>> gpu = traceSceneGpu(
                        shaders, maps, technique.id, technique.defaults, scale, scene);
                    QVERIFY2(gpu.ok(), gpu ? "" : gpu.error().message.c_str());
                    QCOMPARE(gpu->size(), expected.size());
                    for (std::size_t k = 0; k < expected.size(); ++k) {
                        const TraceResult& a = expected[k];
                        const TraceResult& b = (*gpu)[k];
                        const double error = hitErrorTexels(a, b, field.width, field.height);
                        const QString where =
                            QString(
                                "%1 scale %2 polar %3 azimuth %4 ray %5: CPU t %6 (%7 fetches), "
                                "GPU t %8 (%9 fetches), %10 texels apart")
                                .arg(QString::fromUtf8(technique.name.data(),
                                                       int(technique.name.size())))
                                .arg(scale)
                                .arg(polar)
                                .arg(azimuth)
                                .arg(k)
                                .arg(a.t)
                                .arg(a.fetches)
                                .arg(b.t)
                                .arg(b.fetches)
                                .arg(error);
                        QVERIFY2(error <= 1e-3, qPrintable(where));
                        if (bitExact)
                            QVERIFY2(a.fetches == b.fetches, qPrintable(where));
                        QVERIFY2(std::abs(a.fetches - b.fetches) <= 2, qPrintable(where));
                        fetchesDiffer += a.fetches != b.fetches;
                        ++rays;
                        worst = std::max(worst, error);
                    }
                }
            }
        }
    }
    QVERIFY(rays > 10000);
    QVERIFY2(
        fetchesDiffer * 200 <= rays,
        qPrintable(QString("fetch counts differ on %1 of %2 rays").arg(fetchesDiffer).arg(rays)));
    qInfo("%lld rays, fetch counts differ on %lld, largest hit difference %.3g texel", rays,
          fetchesDiffer, worst);
}

// The rays of the long-ray view on which core.trace.LongRayTrace found `cone` 39 texels late (seed
// 71092: t + step rounded through a wall's ridge): on the GPU as on the CPU, and on the exact hit.
void GpuTraceTest::coneOnAFoundLongRay() {
    const HeightField field = makeProceduralMap(ProceduralMap::Walls, 32, 32, 71092);
    TraceMaps maps;
    maps.height = &field;
    maps.wrap = WrapMode::Repeat;
    const ConeMap cone = bakeConeMap(field, maps.wrap, ConeKind::Conservative);
    maps.cone = &cone;
    TraceScene scene;
    scene.rays = 4; // LongRayTrace's 4 x 4 starting points
    scene.polarDeg = 89.99;
    scene.azimuthDeg = 35.0;
    const float scale = 100.0f;
    Result<Tracer> cpu =
        Tracer::create(maps, Technique::Cone, info(Technique::Cone).defaults, scale);
    Result<Tracer> exact =
        Tracer::create(maps, Technique::Exact, info(Technique::Exact).defaults, scale);
    QVERIFY(cpu.ok() && exact.ok());
    const auto expected = traceScene(*cpu, scene);
    const auto hits = traceScene(*exact, scene);
    ShaderCache shaders;
    auto gpu =
        traceSceneGpu(shaders, maps, Technique::Cone, info(Technique::Cone).defaults, scale, scene);
    QVERIFY2(gpu.ok(), gpu ? "" : gpu.error().message.c_str());
    const bool bitExact = test::isLlvmpipe(test::glContext()->info().renderer);
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const QString where = QString("ray %1: exact t %2, CPU t %3, GPU t %4")
                                  .arg(k)
                                  .arg(hits[k].t, 0, 'g', 9)
                                  .arg(expected[k].t, 0, 'g', 9)
                                  .arg((*gpu)[k].t, 0, 'g', 9);
        QVERIFY2(hitErrorTexels(expected[k], (*gpu)[k], field.width, field.height) <= 1e-3,
                 qPrintable(where));
        QVERIFY2(hitErrorTexels(hits[k], (*gpu)[k], field.width, field.height) <= kExactTexels,
                 qPrintable(where));
        if (bitExact)
            QCOMPARE((*gpu)[k].fetches, expected[k].fetches);
    }
}

// Without derived maps in TraceMaps the GPU tracer bakes them as the CPU Tracer does: same answers.
void GpuTraceTest::bakesWhatTheTechniqueReadsWhenNotGiven() {
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 32, 32, 2);
    TraceMaps maps;
    maps.height = &field;
    ShaderCache shaders;
    TraceScene scene;
    scene.rays = 8;
    scene.polarDeg = 70;
    scene.azimuthDeg = 20;
    for (Technique t : {Technique::Cone, Technique::RelaxedCone, Technique::Pyramid}) {
        Result<Tracer> cpu = Tracer::create(maps, t, info(t).defaults, 0.1f);
        QVERIFY(cpu.ok());
        const auto expected = traceScene(*cpu, scene);
        auto gpu = traceSceneGpu(shaders, maps, t, info(t).defaults, 0.1f, scene);
        QVERIFY(gpu.ok());
        for (std::size_t k = 0; k < expected.size(); ++k) {
            QCOMPARE((*gpu)[k].fetches, expected[k].fetches);
            QVERIFY(hitErrorTexels(expected[k], (*gpu)[k], 32, 32) <= 1e-3);
        }
    }
}

void GpuTraceTest::refusesWhatTheCpuRefuses() {
    ShaderCache shaders;
    const HeightField empty;
    TraceMaps maps;
    maps.height = &empty;
    TraceScene scene;
    auto r =
        traceSceneGpu(shaders, maps, Technique::Pom, info(Technique::Pom).defaults, 0.1f, scene);
    QVERIFY(!r.ok());
    QVERIFY(r.error().message.find("empty") != std::string::npos);
    const HeightField field(4, 4, 0.5f);
    maps.height = &field;
    TraceParams bad = info(Technique::Pom).defaults;
    bad.minLayers = 40;
    bad.maxLayers = 8;
    r = traceSceneGpu(shaders, maps, Technique::Pom, bad, 0.1f, scene);
    QVERIFY(!r.ok());
    scene.polarDeg = 90;
    r = traceSceneGpu(shaders, maps, Technique::Pom, info(Technique::Pom).defaults, 0.1f, scene);
    QVERIFY(!r.ok());
}

QTEST_APPLESS_MAIN(GpuTraceTest)
#include "GpuTraceTest.moc"

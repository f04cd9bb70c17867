// The peers' occlusion methods (PeerOcclusion.h): each one's documented values on surfaces whose
// answer is known — a flat map is exactly 1 at every texel, a plane is unoccluded but for
// max-of-sine (which measures elevation from the horizontal), a pit is darker than its rim — on
// both wraps, non-square maps and seeded adversarial maps; and their refusals and cancellation.

#include "parallax/eval/PeerOcclusion.h"

#include "parallax/eval/OcclusionBench.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QtTest>
#include <atomic>
#include <cstdlib>
#include <functional>
#include <random>

using namespace px;

namespace {

using Method =
    std::function<Result<Image>(const HeightField&, const PeerSurfaceOptions&, const BakeControl&)>;

struct Named {
    const char* name;
    Method run;
};

// Each method at small counts (the properties do not depend on them) and the published ones.
std::vector<Named> methods() {
    HbaoOptions hbao;
    HbaoOptions unbiased;
    unbiased.angleBiasDeg = 0.0;
    unbiased.directions = 5;
    unbiased.steps = 7;
    MaxOfSineOptions sine;
    sine.directions = 12;
    sine.steps = 10;
    sine.reachTexels = 10.0;
    SsaoSumOptions ssao;
    ssao.radius = 3;
    RayMarchOptions rays;
    rays.rays = 24;
    rays.distance = 0.3;
    RayMarchOptions unlimited;
    unlimited.rays = 8;
    return {
        {"hbao 8x4", [=](auto& f, auto& s, auto& c) { return hbaoOcclusion(f, s, hbao, c); }},
        {"hbao unbiased",
         [=](auto& f, auto& s, auto& c) { return hbaoOcclusion(f, s, unbiased, c); }},
        {"max-of-sine",
         [=](auto& f, auto& s, auto& c) { return maxOfSineOcclusion(f, s, sine, c); }},
        {"ssao-sum", [=](auto& f, auto& s, auto& c) { return ssaoSumOcclusion(f, s, ssao, c); }},
        {"ray-march", [=](auto& f, auto& s, auto& c) { return rayMarchOcclusion(f, s, rays, c); }},
        {"ray-march unlimited",
         [=](auto& f, auto& s, auto& c) { return rayMarchOcclusion(f, s, unlimited, c); }},
    };
}

unsigned runSeed() {
    const char* given = std::getenv("PX_TEST_SEED");
    const unsigned seed = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                                : std::random_device{}() % 100000u;
    qInfo("map seed %u (PX_TEST_SEED=%u repeats it)", seed, seed);
    return seed;
}

// h = a u + b v over the map (texel centres), so z = s h is one plane.
HeightField plane(int w, int h, double a, double b) {
    HeightField field(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x)
            field.at(x, y) = static_cast<float>(0.2 + a * (x + 0.5) / w + b * (y + 0.5) / h);
    }
    return field;
}

} // namespace

class PeerOcclusionTest : public QObject {
    Q_OBJECT

private slots:
    void flatIsExactlyOneEverywhere();
    void planeIsUnoccludedButForMaxOfSine();
    void pitIsDarkerThanItsRim();
    void adversarialMapsStayInRange();
    void rayMarchIsTheSameEveryRun();
    void refusesBadSettings();
    void cancels();
    void quantileIsTheNearestRank();
    void csvHasTheDocumentedColumns();
};

void PeerOcclusionTest::flatIsExactlyOneEverywhere() {
    for (const auto& [w, h, level] : {std::tuple{16, 16, 0.0f}, {23, 9, 0.5f}, {8, 31, 1.0f}}) {
        const HeightField flat(w, h, level);
        for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
            for (float scale : {0.0f, 0.05f, 2.0f}) {
                for (const Named& m : methods()) {
                    Result<Image> ao = m.run(flat, {scale, wrap}, {});
                    QVERIFY2(ao.ok(), m.name);
                    QCOMPARE(ao->width, w);
                    QCOMPARE(ao->height, h);
                    QCOMPARE(ao->channels, 1);
                    for (float v : ao->pixels)
                        QVERIFY2(v == 1.0f, qPrintable(QString("%1: %2 on %3x%4 %5")
                                                           .arg(m.name)
                                                           .arg(v)
                                                           .arg(w)
                                                           .arg(h)
                                                           .arg(toString(wrap).data())));
                }
            }
        }
    }
}

// A plane rising along u, clamped: beyond its low edge the surface stays flat (a concave bend), so
// texels within a method's reach of that edge are left out, as is the unlimited ray cast. Every
// method but max-of-sine reads the tangent plane: within 1e-6 of 1. Max-of-sine darkens every
// texel that looks uphill.
void PeerOcclusionTest::planeIsUnoccludedButForMaxOfSine() {
    const HeightField tilted = plane(64, 40, 0.6, 0.0);
    for (const Named& m : methods()) {
        if (std::string(m.name) == "ray-march unlimited")
            continue;
        Result<Image> ao = m.run(tilted, {0.3f, WrapMode::Clamp}, {});
        QVERIFY2(ao.ok(), m.name);
        const bool sine = std::string(m.name) == "max-of-sine";
        const ImageWriter got = ao->writer();
        float darkest = 1.0f;
        for (int y = 0; y < 40; ++y) {
            for (int x = 24; x < 64; ++x)
                darkest = std::min(darkest, got.at(x, y));
        }
        if (sine)
            QVERIFY2(darkest < 0.99f, qPrintable(QString::number(darkest)));
        else
            QVERIFY2(darkest >= 1.0f - 1e-6f,
                     qPrintable(QString("%1: %2").arg(m.name).arg(darkest)));
    }
}

// A one-texel-wide pit 3 texels deep in scale terms: its floor sees a small cone of sky.
void PeerOcclusionTest::pitIsDarkerThanItsRim() {
    HeightField field(21, 21, 1.0f);
    field.at(10, 10) = 0.0f;
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
        for (const Named& m : methods()) {
            Result<Image> ao = m.run(field, {0.2f, wrap}, {});
            QVERIFY2(ao.ok(), m.name);
            const ImageWriter got = ao->writer();
            QVERIFY2(got.at(10, 10) < 0.9f,
                     qPrintable(QString("%1: %2").arg(m.name).arg(got.at(10, 10))));
            QVERIFY2(got.at(10, 10) < got.at(2, 2), m.name);
            QVERIFY2(got.at(2, 2) == 1.0f || std::string(m.name).starts_with("ray-march"),
                     m.name); // far from the pit: a flat top
        }
    }
}

// Spikes, walls, pits, terraces and JPEG noise, non-square, both wraps: every texel in [0, 1],
// never NaN.
void PeerOcclusionTest::adversarialMapsStayInRange() {
    const unsigned seed = runSeed();
    for (ProceduralMap kind : {ProceduralMap::SpikeFlat, ProceduralMap::Walls, ProceduralMap::Pits,
                               ProceduralMap::Terraces, ProceduralMap::Jpeg}) {
        const HeightField field = makeProceduralMap(kind, 29, 18, seed);
        for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
            for (const Named& m : methods()) {
                Result<Image> ao = m.run(field, {0.1f, wrap}, {});
                QVERIFY2(ao.ok(), m.name);
                for (float v : ao->pixels) // NaN fails both comparisons
                    QVERIFY2(v >= 0.0f && v <= 1.0f,
                             qPrintable(QString("%1: %2").arg(m.name).arg(v)));
            }
        }
    }
}

void PeerOcclusionTest::rayMarchIsTheSameEveryRun() {
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 32, 20, 3);
    RayMarchOptions o;
    o.rays = 16;
    o.distance = 0.25;
    const Image a = *rayMarchOcclusion(field, {0.1f, WrapMode::Repeat}, o);
    QVERIFY(rayMarchOcclusion(field, {0.1f, WrapMode::Repeat}, o)->pixels == a.pixels);
    o.seed = 2;
    QVERIFY(rayMarchOcclusion(field, {0.1f, WrapMode::Repeat}, o)->pixels != a.pixels);
}

void PeerOcclusionTest::refusesBadSettings() {
    const HeightField field(4, 4, 0.5f);
    QCOMPARE(QString::fromStdString(hbaoOcclusion(HeightField{}, {}, {}).error().message),
             QString("the height map is empty"));
    QCOMPARE(QString::fromStdString(
                 ssaoSumOcclusion(field, {-1.0f, WrapMode::Repeat}, {}).error().message),
             QString("the height scale must be a finite number >= 0"));
    HbaoOptions hbao;
    hbao.radius = 0.0;
    QVERIFY(!hbaoOcclusion(field, {}, hbao).ok());
    MaxOfSineOptions sine;
    sine.steps = 0;
    QVERIFY(!maxOfSineOcclusion(field, {}, sine).ok());
    SsaoSumOptions ssao;
    ssao.radius = 0;
    QVERIFY(!ssaoSumOcclusion(field, {}, ssao).ok());
    RayMarchOptions rays;
    rays.distance = std::nan("");
    QCOMPARE(QString::fromStdString(rayMarchOcclusion(field, {}, rays).error().message),
             QString("the ray cast needs at least one ray, a distance > 0 and a step > 0"));
}

void PeerOcclusionTest::cancels() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 64, 64);
    std::atomic<bool> stop{true};
    BakeControl control;
    control.cancel = &stop;
    for (const Named& m : methods()) {
        Result<Image> ao = m.run(field, {}, control);
        QVERIFY2(!ao.ok() && isCancelled(ao.error()), m.name);
    }
    // Progress ends at 1 on success.
    float last = 0.0f;
    BakeControl watched;
    watched.progress = [&](float f) { last = f; };
    QVERIFY(hbaoOcclusion(field, {}, {}, watched).ok());
    QCOMPARE(last, 1.0f);
}

void PeerOcclusionTest::quantileIsTheNearestRank() {
    std::vector<double> values;
    for (int i = 1000; i >= 1; --i)
        values.push_back(i);
    QCOMPARE(nearestRankQuantile(values, 0.999), 999.0);
    QCOMPARE(nearestRankQuantile(values, 1.0), 1000.0);
    QCOMPARE(nearestRankQuantile(values, 0.0), 1.0);
    std::vector<double> none;
    QCOMPARE(nearestRankQuantile(none, 0.5), 0.0);
}

void PeerOcclusionTest::csvHasTheDocumentedColumns() {
    OcclusionBenchReport report;
    report.distance = std::numeric_limits<double>::infinity();
    OcclusionBenchRow row{"bricks 64", 64, 64, "hbao", "8x4, Material Maker", 32};
    row.texels = 4096;
    row.meanSteps = 1.5;
    row.p999Steps = 12.25;
    row.maxSteps = 20;
    row.seconds = 0.004096;
    report.rows.push_back(row);
    row.map = "all";
    report.pooled.push_back(row);
    const QStringList lines = QString::fromStdString(occlusionBenchCsv(report)).split('\n');
    QCOMPARE(lines.size(), 4); // header, a row, the pooled row, the empty end
    QCOMPARE(lines[0], QString::fromUtf8(kOcclusionBenchCsvHeader.data()));
    QCOMPARE(lines[1], QString("bricks 64,64,64,4096,repeat,0.05,inf,1024,hbao,\"8x4, Material "
                               "Maker\",32,1.5000,12.2500,20.0000,0.004096,1000.0"));
    QVERIFY(lines[2].startsWith("all,"));
}

QTEST_GUILESS_MAIN(PeerOcclusionTest)
#include "PeerOcclusionTest.moc"

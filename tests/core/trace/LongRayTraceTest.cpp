// Float32 `exact`, `pyramid`, `cone` and `relaxed-cone` on the longest rays the tracers accept
// (height scale 100, polar 89° and 89.99°: |P| at or near its bound of 10^4 uv, up to a million
// cells) against the float64 walk of tests/support/DoubleWalk.h, on noise and the adversarial
// maps, seeds 1, 2, 76347, 31684 and one that changes on every run (printed; PX_TEST_SEED=N
// repeats it; runs found 76347: `cone` stepped a thousandth of a texel past a wall's face, and
// 31684: `relaxed-cone` read a peak's cell where the ray was already beside it). Every
// ray within 0.05 texel of the float64 hit (relaxed-cone: 2 texels, its documented bound), or,
// where the ray grazes the surface, the float64 hit of the surface raised or lowered by 2^-22 (a
// few float32 ulps of a height): nothing else is allowed. A row is a polar angle, with
// every map class, seed and technique: each ray's float64 walk is shared by the four techniques.
// Single rays a per-run seed found off their bound are kept as rows of their own
// (foundRaysMatchADoubleWalk), each traced by every technique: a whole seed costs seconds.

#include "DoubleWalk.h"
#include "TestSupport.h"
#include "parallax/eval/HitErrorStats.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/Technique.h"
#include "parallax/trace/TraceScene.h"
#include "trace/TraceKernel.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

using namespace px;

class LongRayTraceTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void exactMatchesADoubleWalk_data();
    void exactMatchesADoubleWalk();
    void foundRaysMatchADoubleWalk_data();
    void foundRaysMatchADoubleWalk();

private:
    unsigned m_seed = 4;
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

HeightField shifted(const HeightField& field, float by) {
    HeightField out = field;
    for (float& h : out.texels)
        h += by;
    return out;
}

constexpr Technique kTechniques[] = {Technique::Exact, Technique::Pyramid, Technique::Cone,
                                     Technique::RelaxedCone};
constexpr float kScale = 100.0f;

// A technique's bound in texels from the float64 hit.
double boundOf(Technique technique) {
    return technique == Technique::RelaxedCone ? kWrongSurfaceTexels : kExactTexels;
}

// Ray k of a view: the 4 x 4 grid of starting points over the tile.
glm::dvec2 rayStart(int k) {
    const int column = k % 4;
    const int row = k / 4;
    return {(column + 0.5) / 4.0, (row + 0.5) / 4.0};
}

// How far, in texels, a traced t lies outside the float64 hits of the surface raised and lowered
// by 2^-22: 0 if it lies between them (the ray grazes the surface within a few float32 ulps).
double outsideTheGraze(const HeightField& field, WrapMode wrap, glm::dvec2 uv0, glm::dvec2 P,
                       double traced, double texelsPerT) {
    const float eps = std::ldexp(1.0f, -22);
    const double tHigh = test::doubleWalkT(shifted(field, eps), wrap, uv0, P);
    const double tLow = test::doubleWalkT(shifted(field, -eps), wrap, uv0, P);
    return std::max({0.0, tHigh - traced, traced - tLow}) * texelsPerT;
}

QString describeRay(Technique technique, ProceduralMap map, unsigned seed, WrapMode wrap,
                    double azimuth, int k, double traced, double t, double error) {
    return QString("%1: %2, seed %3, %4, azimuth %5, ray %6: float t %7, double t %8 (%9 texels)")
        .arg(info(technique).name.data(),
             proceduralMapNames()[static_cast<std::size_t>(map)].data())
        .arg(seed)
        .arg(wrap == WrapMode::Repeat ? "repeat" : "clamp")
        .arg(azimuth)
        .arg(k)
        .arg(traced, 0, 'g', 9)
        .arg(t, 0, 'g', 12)
        .arg(error);
}

} // namespace

void LongRayTraceTest::initTestCase() {
    const char* given = std::getenv("PX_TEST_SEED");
    m_seed = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                   : 4u + std::random_device{}() % 100000u;
    qInfo("map seeds 1, 2, 76347, 31684 and %u (PX_TEST_SEED=%u repeats it)", m_seed, m_seed);
}

void LongRayTraceTest::exactMatchesADoubleWalk_data() {
    QTest::addColumn<double>("polar");
    // ctest runs the rows in shards, in parallel and each within its time budget (TestSupport.h).
    // A row holds every technique and seed: the float64 walk of a ray, the costly part, is done
    // once for all four techniques, and each technique's grazing rays are counted over all seeds.
    const test::TestShard shard = test::testShard();
    std::size_t row = 0;
    for (double polar : {89.0, 89.99}) // 89.9° is bounded to the same ray as 89.99°
        if (shard.takes(row++))
            QTest::addRow("polar %g", polar) << polar;
    QVERIFY(row >= shard.count); // every shard has a row
}

namespace {

// What one technique met over a row's rays.
struct Tally {
    double worst = 0.0;
    QString where;
    int rays = 0, grazing = 0;
};

} // namespace

void LongRayTraceTest::exactMatchesADoubleWalk() {
    QFETCH(double, polar);
    Tally tally[std::size(kTechniques)];
    for (const Class& c : kClasses) {
        for (unsigned seed : {1u, 2u, 76347u, 31684u, m_seed}) {
            const HeightField field = makeProceduralMap(c.map, c.width, c.height, seed);
            for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
                std::vector<Tracer> tracers;
                for (Technique technique : kTechniques) {
                    auto tracer = test::makeTracer(field, wrap, technique, kScale);
                    QVERIFY(tracer.ok());
                    tracers.push_back(std::move(*tracer));
                }
                for (double azimuth : {35.0, 90.0, 200.0}) {
                    const glm::vec2 view = parallaxVector(kScale, polar, azimuth);
                    const glm::dvec2 P(boundedParallax(kScale, polar, azimuth));
                    const double texelsPerT = std::hypot(P.x * field.width, P.y * field.height);
                    for (int k = 0; k < 16; ++k) {
                        const glm::dvec2 uv0 = rayStart(k);
                        const double t = test::doubleWalkT(field, wrap, uv0, P);
                        for (std::size_t i = 0; i < std::size(kTechniques); ++i) {
                            const double bound = boundOf(kTechniques[i]);
                            const TraceResult r = tracers[i].trace(uv0, view);
                            const double e = std::abs(r.t - t) * texelsPerT;
                            Tally& y = tally[i];
                            ++y.rays;
                            const QString ray = describeRay(kTechniques[i], c.map, seed, wrap,
                                                            azimuth, k, r.t, t, e);
                            if (!(e <= y.worst)) {
                                y.worst = e;
                                y.where = ray;
                            }
                            if (e <= bound)
                                continue;
                            const double outside =
                                outsideTheGraze(field, wrap, uv0, P, r.t, texelsPerT);
                            QVERIFY2(outside <= bound,
                                     qPrintable(ray + QString(", %1 texels outside the hits of the "
                                                              "surface moved by 2^-22")
                                                          .arg(outside)));
                            ++y.grazing;
                        }
                    }
                }
            }
        }
    }
    for (std::size_t i = 0; i < std::size(kTechniques); ++i) {
        const Tally& y = tally[i];
        qInfo("%s, polar %g: %d rays, the farthest %g texels from the float64 walk (%s); %d "
              "grazing rays",
              info(kTechniques[i]).name.data(), polar, y.rays, y.worst, qPrintable(y.where),
              y.grazing);
        QVERIFY2(y.grazing * 100 <= y.rays, qPrintable(QString("%1: %2 grazing rays")
                                                           .arg(info(kTechniques[i]).name.data())
                                                           .arg(y.grazing)));
    }
}

void LongRayTraceTest::foundRaysMatchADoubleWalk_data() {
    QTest::addColumn<unsigned>("seed");
    QTest::addColumn<double>("polar");
    QTest::addColumn<double>("azimuth");
    QTest::addColumn<int>("ray");
    // Every shard runs these few rays (milliseconds), all on `walls` 32 x 32, repeat. `cone`:
    // t + step rounded 2.4e-4 texel past the ridge of a wall the ray clips, through its tip and out
    // the other side, above the surface again (seed 71092: 39 texels late); a cone-only sweep of
    // 150 seeds of `walls` found 9 more such seeds, at 89 degrees too: one ray of some of them.
    struct Found {
        unsigned seed;
        double polar, azimuth;
        int ray;
    };
    for (const Found& f : {Found{71092u, 89.99, 35.0, 3}, Found{5354u, 89.99, 200.0, 2},
                           Found{51754u, 89.99, 35.0, 1}, Found{2961u, 89.0, 200.0, 1},
                           Found{39295u, 89.0, 200.0, 3}})
        QTest::addRow("walls %u repeat %g az%g ray%d", f.seed, f.polar, f.azimuth, f.ray)
            << f.seed << f.polar << f.azimuth << f.ray;
}

// Each ray traced by every technique, held to the bounds of exactMatchesADoubleWalk.
void LongRayTraceTest::foundRaysMatchADoubleWalk() {
    QFETCH(unsigned, seed);
    QFETCH(double, polar);
    QFETCH(double, azimuth);
    QFETCH(int, ray);
    const WrapMode wrap = WrapMode::Repeat;
    const HeightField field = makeProceduralMap(ProceduralMap::Walls, 32, 32, seed);
    const glm::vec2 view = parallaxVector(kScale, polar, azimuth);
    const glm::dvec2 P(boundedParallax(kScale, polar, azimuth));
    const double texelsPerT = std::hypot(P.x * field.width, P.y * field.height);
    const glm::dvec2 uv0 = rayStart(ray);
    const double t = test::doubleWalkT(field, wrap, uv0, P);
    for (Technique technique : kTechniques) {
        auto tracer = test::makeTracer(field, wrap, technique, kScale);
        QVERIFY(tracer.ok());
        const TraceResult r = tracer->trace(uv0, view);
        const double e = std::abs(r.t - t) * texelsPerT;
        const QString what =
            describeRay(technique, ProceduralMap::Walls, seed, wrap, azimuth, ray, r.t, t, e);
        qInfo("%s", qPrintable(what));
        const double bound = boundOf(technique);
        if (e <= bound)
            continue;
        const double outside = outsideTheGraze(field, wrap, uv0, P, r.t, texelsPerT);
        QVERIFY2(outside <= bound,
                 qPrintable(what + QString(", %1 texels outside the hits of the surface moved by "
                                           "2^-22")
                                       .arg(outside)));
    }
}

QTEST_APPLESS_MAIN(LongRayTraceTest)
#include "LongRayTraceTest.moc"

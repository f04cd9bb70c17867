// Ambient occlusion and bent normals (docs/conventions.md §7): every texel against a reference that
// shares nothing with the baker (OcclusionReference.h), closed forms, the default azimuth count's
// error against many azimuths, and the usual bake contract (errors, progress, cancellation).
// Adversarial maps change from run to run (PX_TEST_SEED=N repeats one).

#include "parallax/bake/OcclusionBaker.h"

#include "OcclusionReference.h"
#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"
#include "sample/AdversarialMaps.h"

#include <QtTest>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace px;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

unsigned runSeed() {
    static const unsigned seed = [] {
        const char* given = std::getenv("PX_TEST_SEED");
        const unsigned s = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                                 : std::random_device{}() % 100000u;
        qInfo("adversarial map seed %u (PX_TEST_SEED=%u repeats it)", s, s);
        return s;
    }();
    return seed;
}

OcclusionMaps bake(const HeightField& f, double scale, double distance, WrapMode wrap,
                   int directions, OcclusionOutputs outputs = OcclusionOutputs::Both) {
    OcclusionBakeOptions o;
    o.heightScale = static_cast<float>(scale);
    o.distance = distance;
    o.wrap = wrap;
    o.directions = directions;
    Result<OcclusionMaps> r = bakeOcclusion(f, o, outputs);
    if (!r)
        qFatal("bake failed: %s", r.error().message.c_str());
    return *r;
}

glm::dvec3 bentAt(const Image& bent, int x, int y) {
    return glm::dvec3(bent.at(x, y, 0), bent.at(x, y, 1), bent.at(x, y, 2)) * 2.0 - 1.0;
}

double degreesBetween(glm::dvec3 a, glm::dvec3 b) {
    const double c = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

struct MapCase {
    const char* name;
    ProceduralMap kind;
    int width, height;
    double scale;
};

// Samples, adversarial classes (seeded per run), non-square and one-texel-wide maps.
const MapCase kExactCases[] = {
    {"noise", ProceduralMap::Noise, 24, 20, 0.1},
    {"rivets", ProceduralMap::Rivets, 20, 24, 0.08},
    {"random", ProceduralMap::Random, 12, 10, 0.02},
    {"checker", ProceduralMap::Checker, 10, 10, 0.02},
    {"spikes", ProceduralMap::Spikes, 20, 16, 0.05},
    {"spike-flat", ProceduralMap::SpikeFlat, 22, 8, 0.05},
    {"walls", ProceduralMap::Walls, 18, 14, 0.05},
    {"terraces", ProceduralMap::Terraces, 20, 20, 0.1},
    {"jpeg", ProceduralMap::Jpeg, 20, 18, 0.1},
    {"pits", ProceduralMap::Pits, 16, 16, 0.05},
    {"column", ProceduralMap::Random, 1, 9, 0.05},
    {"row", ProceduralMap::Random, 7, 1, 0.05},
};

HeightField makeMap(const MapCase& c) {
    return isAdversarial(c.kind) ? makeAdversarialMap(c.kind, c.width, c.height, runSeed())
                                 : makeProceduralMap(c.kind, c.width, c.height, runSeed());
}

} // namespace

class OcclusionBakerTest : public QObject {
    Q_OBJECT

private slots:
    void matchesReferenceEverywhere_data();
    void matchesReferenceEverywhere();
    void flatAndPlanesAreUnoccluded();
    void wallBesideFloor();
    void vGroove();
    void hemisphericalPit();
    void defaultDirectionsAreEnough_data();
    void defaultDirectionsAreEnough();
    void outputsAndGreen();
    void rejectsBadInput();
    void cancelsAndReportsProgress();
};

void OcclusionBakerTest::matchesReferenceEverywhere_data() {
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("wrap");
    QTest::addColumn<double>("distance");
    std::size_t row = 0; // ctest runs the rows in shards (px_shard_test)
    for (int i = 0; i < static_cast<int>(std::size(kExactCases)); ++i) {
        for (int w = 0; w < 2; ++w) {
            for (double d : {0.2, kInf}) {
                if (!test::testShard().takes(row++))
                    continue;
                const QByteArray name = QByteArray(kExactCases[i].name) +
                                        (w ? " clamp" : " repeat") +
                                        (d < kInf ? " D=0.2" : " D=inf");
                QTest::newRow(name.constData()) << i << w << d;
            }
        }
    }
}

// With the same azimuths, the bake is the reference at every texel: exact horizons (every crossed
// cell, the own slope) and the exact integral. An unlimited search on repeat stops where nothing
// can raise a horizon's tangent by more than 2^-14 (OcclusionHorizon.h), hence its looser bound.
void OcclusionBakerTest::matchesReferenceEverywhere() {
    QFETCH(int, index);
    QFETCH(int, wrap);
    QFETCH(double, distance);
    const MapCase& c = kExactCases[index];
    const WrapMode mode = wrap ? WrapMode::Clamp : WrapMode::Repeat;
    const HeightField field = makeMap(c);
    const int azimuths = 32;
    const OcclusionMaps maps = bake(field, c.scale, distance, mode, azimuths);
    test::OcclusionReferenceSettings ref;
    ref.scale = static_cast<float>(c.scale);
    ref.distance = distance;
    ref.wrap = mode;
    ref.azimuths = azimuths;
    const bool loose = mode == WrapMode::Repeat && std::isinf(distance);
    const double aoTolerance = loose ? 3e-4 : 2e-5;
    const double degreeTolerance = loose ? 0.05 : 0.01;
    double worstAo = 0.0, worstDegrees = 0.0;
    for (int y = 0; y < field.height; ++y) {
        for (int x = 0; x < field.width; ++x) {
            const test::ReferenceOcclusion r = test::referenceOcclusion(field, ref, x, y);
            const double ao = maps.occlusion.at(x, y);
            const double degrees = degreesBetween(bentAt(maps.bentNormals, x, y), r.bent);
            worstAo = std::max(worstAo, std::abs(ao - r.ao));
            worstDegrees = std::max(worstDegrees, degrees);
            if (std::abs(ao - r.ao) > aoTolerance || degrees > degreeTolerance)
                QFAIL(qPrintable(QString("texel (%1, %2): AO %3, reference %4; bent normal %5 "
                                         "degrees off (seed %6)")
                                     .arg(x)
                                     .arg(y)
                                     .arg(ao, 0, 'g', 9)
                                     .arg(r.ao, 0, 'g', 9)
                                     .arg(degrees)
                                     .arg(runSeed())));
        }
    }
    qInfo("worst: AO %.2e, bent normal %.4f degrees", worstAo, worstDegrees);
}

// Nothing rises above a point's own tangent plane: AO exactly 1 and the bent normal the normal.
// Flat maps with either wrap and any distance; planes with clamp, at texels whose disc of radius D
// stays on the plane (beyond the edges the clamped surface is flat, which does occlude).
void OcclusionBakerTest::flatAndPlanesAreUnoccluded() {
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
        for (double d : {0.1, kInf}) {
            const HeightField flat(13, 7, 0.375f);
            const OcclusionMaps maps = bake(flat, 0.3, d, wrap, 0);
            for (float v : maps.occlusion.pixels)
                QCOMPARE(v, 1.0f);
            for (int y = 0; y < 7; ++y) {
                for (int x = 0; x < 13; ++x)
                    QVERIFY(degreesBetween(bentAt(maps.bentNormals, x, y), {0, 0, 1}) < 1e-4);
            }
        }
    }
    // Dyadic planes (exact differences) and others, steep and shallow, in several directions.
    std::mt19937 rng(runSeed());
    std::uniform_real_distribution<float> slope(-0.02f, 0.02f);
    for (int trial = 0; trial < 6; ++trial) {
        const int W = 40, H = 32;
        const bool dyadic = trial < 2;
        const float a = dyadic ? (trial ? 1.0f / 64 : -3.0f / 256) : slope(rng);
        const float b = dyadic ? (trial ? -1.0f / 128 : 5.0f / 512) : slope(rng);
        HeightField plane(W, H);
        const int cx = W / 2, cy = H / 2; // the plane's level point: a whole texel
        for (int y = 0; y < H; ++y) {
            for (int x = 0; x < W; ++x)
                plane.at(x, y) =
                    0.5f + a * static_cast<float>(x - cx) + b * static_cast<float>(y - cy);
        }
        const double D = 6.0 / W; // 6 texels across, 4.8 down
        const OcclusionMaps maps = bake(plane, 2.0, D, WrapMode::Clamp, 0);
        const glm::dvec3 n = glm::normalize(glm::dvec3(-2.0 * a * W, 2.0 * b * H, 1.0));
        for (int y = 6; y < H - 6; ++y) {
            for (int x = 7; x < W - 7; ++x) {
                const float ao = maps.occlusion.at(x, y);
                if (dyadic)
                    QCOMPARE(ao, 1.0f);
                else
                    QVERIFY2(ao >= 1.0f - 1e-6f, qPrintable(QString::number(ao, 'g', 9)));
                QVERIFY(degreesBetween(bentAt(maps.bentNormals, x, y), n) < 1e-3);
            }
        }
    }
}

// A floor beside a wall of height Hw whose face is X away, endless along the wall (clamp extends
// both): in azimuth phi the horizon is atan(Hw cos phi / X), so AO = 1/2 + 1 / (2 sqrt(1 + k^2)),
// k = Hw / X; the bent normal leans away from the wall.
void OcclusionBakerTest::wallBesideFloor() {
    const int W = 64, H = 16;
    HeightField field(W, H, 0.0f);
    for (int y = 0; y < H; ++y) {
        for (int x = 48; x < W; ++x)
            field.at(x, y) = 1.0f;
    }
    const double s = 0.2;
    const OcclusionMaps maps = bake(field, s, kInf, WrapMode::Clamp, 1024);
    for (int x : {10, 30, 40, 46}) {
        const double k = s / ((48.0 - x) / W);
        const double expected = 0.5 + 0.5 / std::sqrt(1.0 + k * k);
        for (int y = 0; y < H; ++y) {
            QVERIFY2(std::abs(maps.occlusion.at(x, y) - expected) < 1e-4,
                     qPrintable(QString("x %1: %2, expected %3")
                                    .arg(x)
                                    .arg(maps.occlusion.at(x, y))
                                    .arg(expected)));
            const glm::dvec3 b = bentAt(maps.bentNormals, x, y);
            QVERIFY(b.x < 0.0);
            QVERIFY(std::abs(b.y) < 1e-5);
        }
    }
}

// At the bottom of a V-groove with walls of slope g (endless along the groove), every azimuth's
// horizon is the wall's slope along it, and AO = 1 / sqrt(1 + g^2): the cosine of the wall angle.
void OcclusionBakerTest::vGroove() {
    const int W = 41, H = 9;
    HeightField field(W, H);
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x)
            field.at(x, y) = std::abs(x - 20) / 20.0f;
    }
    const double s = 0.25;
    const double g = s * W / 20.0; // rise per uv
    const OcclusionMaps maps = bake(field, s, 19.0 / W, WrapMode::Clamp, 2048);
    for (int y = 0; y < H; ++y) {
        QVERIFY(std::abs(maps.occlusion.at(20, y) - 1.0 / std::sqrt(1.0 + g * g)) < 1e-5);
        QVERIFY(degreesBetween(bentAt(maps.bentNormals, 20, y), {0, 0, 1}) < 1e-3);
    }
}

// The bottom of a hemispherical pit sees its rim at 45 degrees all round: AO = 1/2. The sampled
// rim lies at most a texel diagonal outside the sphere, so the bake is at most a little above.
void OcclusionBakerTest::hemisphericalPit() {
    const int N = 160;
    const double R = 60.0; // texels
    HeightField field(N, N, 1.0f);
    for (int y = 0; y < N; ++y) {
        for (int x = 0; x < N; ++x) {
            const double rho2 = (x - 80.0) * (x - 80.0) + (y - 80.0) * (y - 80.0);
            if (rho2 < R * R)
                field.at(x, y) = static_cast<float>(1.0 - std::sqrt(R * R - rho2) / R);
        }
    }
    const double s = R / N; // depth R in uv, as the radius
    // Beyond the rim nothing rises: a distance just past it gives the unlimited horizon.
    const OcclusionMaps maps = bake(field, s, (R + 4.0) / N, WrapMode::Repeat, 64);
    const double ao = maps.occlusion.at(80, 80);
    const double rimLow = R / (R + std::sqrt(2.0)); // the flattest rim tangent sampling allows
    const double highest = 1.0 - 0.5 * rimLow * rimLow / (1.0 + rimLow * rimLow) * 2.0;
    QVERIFY2(ao >= 0.5 - 1e-6 && ao <= highest, qPrintable(QString::number(ao, 'g', 9)));
}

void OcclusionBakerTest::defaultDirectionsAreEnough_data() {
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("wrap");
    QTest::addColumn<double>("distance");
    QTest::addColumn<double>("scale");
    const struct {
        ProceduralMap kind;
        double scale;
    } maps[] = {{ProceduralMap::Noise, 0.1},   {ProceduralMap::Bricks, 0.05},
                {ProceduralMap::Stones, 0.08}, {ProceduralMap::Rivets, 0.08},
                {ProceduralMap::Random, 0.02}, {ProceduralMap::Spikes, 0.05},
                {ProceduralMap::Walls, 0.05},  {ProceduralMap::Terraces, 0.1},
                {ProceduralMap::Jpeg, 0.1},    {ProceduralMap::Outliers, 0.1}};
    std::size_t row = 0;
    for (const auto& m : maps) {
        for (int w = 0; w < 2; ++w) {
            for (double d : {0.1, kInf}) {
                if (!test::testShard().takes(row++))
                    continue;
                const QByteArray name =
                    QByteArray(proceduralMapNames()[static_cast<int>(m.kind)].data()) +
                    (w ? " clamp" : " repeat") + (d < kInf ? " D=0.1" : " D=inf");
                QTest::newRow(name.constData()) << static_cast<int>(m.kind) << w << d << m.scale;
            }
        }
    }
}

// The default azimuth count against 512 azimuths (the bake itself, exact per azimuth as
// matchesReferenceEverywhere shows): within 0.5/255 on average and 2/255 at p99.9, and every
// texel within 8/255.
void OcclusionBakerTest::defaultDirectionsAreEnough() {
    QFETCH(int, kind);
    QFETCH(int, wrap);
    QFETCH(double, distance);
    QFETCH(double, scale);
    const auto k = static_cast<ProceduralMap>(kind);
    const HeightField field = isAdversarial(k) ? makeAdversarialMap(k, 48, 40, runSeed())
                                               : makeProceduralMap(k, 48, 40, runSeed());
    const WrapMode mode = wrap ? WrapMode::Clamp : WrapMode::Repeat;
    const Image fine =
        bake(field, scale, distance, mode, 1024, OcclusionOutputs::AmbientOcclusion).occlusion;
    const Image coarse =
        bake(field, scale, distance, mode, 0, OcclusionOutputs::AmbientOcclusion).occlusion;
    std::vector<double> errors;
    for (std::size_t i = 0; i < fine.pixels.size(); ++i)
        errors.push_back(std::abs(double(coarse.pixels[i]) - double(fine.pixels[i])) * 255.0);
    std::sort(errors.begin(), errors.end());
    double mean = 0.0;
    for (double e : errors)
        mean += e / static_cast<double>(errors.size());
    const double p999 = errors[static_cast<std::size_t>(0.999 * (errors.size() - 1))];
    qInfo("mean %.3f, p99.9 %.3f, max %.3f (8-bit steps)", mean, p999, errors.back());
    QVERIFY2(mean <= 0.5 && p999 <= 2.0 && errors.back() <= 8.0,
             qPrintable(QString("mean %1, p99.9 %2, max %3 (seed %4)")
                            .arg(mean)
                            .arg(p999)
                            .arg(errors.back())
                            .arg(runSeed())));
}

// Asking for one output leaves the other empty; DirectX green is 1 - G and nothing else changes.
void OcclusionBakerTest::outputsAndGreen() {
    const HeightField field = makeProceduralMap(ProceduralMap::Rivets, 24, 24);
    const OcclusionMaps both = bake(field, 0.1, 0.2, WrapMode::Repeat, 16);
    const OcclusionMaps aoOnly =
        bake(field, 0.1, 0.2, WrapMode::Repeat, 16, OcclusionOutputs::AmbientOcclusion);
    const OcclusionMaps bentOnly =
        bake(field, 0.1, 0.2, WrapMode::Repeat, 16, OcclusionOutputs::BentNormals);
    QCOMPARE(aoOnly.occlusion.channels, 1);
    QVERIFY(aoOnly.bentNormals.empty());
    QVERIFY(bentOnly.occlusion.empty());
    QCOMPARE(bentOnly.bentNormals.channels, 3);
    QVERIFY(aoOnly.occlusion.pixels == both.occlusion.pixels);
    QVERIFY(bentOnly.bentNormals.pixels == both.bentNormals.pixels);
    bool occluded = false;
    for (float v : both.occlusion.pixels)
        occluded = occluded || v < 0.9f;
    QVERIFY(occluded);

    OcclusionBakeOptions o;
    o.heightScale = 0.1f;
    o.distance = 0.2;
    o.directions = 16;
    o.green = NormalGreen::DirectX;
    const Image dx = bakeOcclusion(field, o, OcclusionOutputs::BentNormals)->bentNormals;
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 24; ++x) {
            QCOMPARE(dx.at(x, y, 0), both.bentNormals.at(x, y, 0));
            QCOMPARE(dx.at(x, y, 1), 1.0f - both.bentNormals.at(x, y, 1));
            QCOMPARE(dx.at(x, y, 2), both.bentNormals.at(x, y, 2));
        }
    }
}

void OcclusionBakerTest::rejectsBadInput() {
    const HeightField field(4, 4, 0.5f);
    const auto fails = [](const HeightField& f, OcclusionBakeOptions o, const char* words) {
        Result<OcclusionMaps> r = bakeOcclusion(f, o, OcclusionOutputs::Both);
        return !r && r.error().message.find(words) != std::string::npos;
    };
    QVERIFY(fails(HeightField{}, {}, "empty"));
    OcclusionBakeOptions o;
    o.heightScale = -1.0f;
    QVERIFY(fails(field, o, "height scale"));
    o.heightScale = std::numeric_limits<float>::quiet_NaN();
    QVERIFY(fails(field, o, "height scale"));
    for (double d : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
        o = {};
        o.distance = d;
        QVERIFY(fails(field, o, "distance"));
    }
    for (int n : {-1, kMaxOcclusionDirections + 1}) {
        o = {};
        o.directions = n;
        QVERIFY(fails(field, o, "directions"));
    }
    o = {};
    o.directions = kMaxOcclusionDirections;
    QVERIFY(static_cast<bool>(bakeOcclusion(field, o, OcclusionOutputs::AmbientOcclusion)));
    QCOMPARE(occlusionDirections(OcclusionBakeOptions{}), kDefaultOcclusionDirections);
}

void OcclusionBakerTest::cancelsAndReportsProgress() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 64, 64);
    std::vector<float> reported;
    BakeControl control;
    control.progress = [&](float f) { reported.push_back(f); };
    OcclusionBakeOptions o;
    o.directions = 8;
    QVERIFY(static_cast<bool>(bakeOcclusion(field, o, OcclusionOutputs::Both, control)));
    QVERIFY(!reported.empty());
    QVERIFY(std::is_sorted(reported.begin(), reported.end()));
    QCOMPARE(reported.back(), 1.0f);

    std::atomic<bool> stop{true};
    BakeControl cancelled;
    cancelled.cancel = &stop;
    Result<OcclusionMaps> r = bakeOcclusion(field, o, OcclusionOutputs::Both, cancelled);
    QVERIFY(!r && isCancelled(r.error()));
    // Cancelled half way through, from the progress callback.
    std::atomic<bool> later{false};
    BakeControl midway;
    midway.cancel = &later;
    midway.progress = [&](float f) {
        if (f >= 0.5f)
            later = true;
    };
    r = bakeOcclusion(field, o, OcclusionOutputs::Both, midway);
    QVERIFY(!r && isCancelled(r.error()));
}

QTEST_GUILESS_MAIN(OcclusionBakerTest)
#include "OcclusionBakerTest.moc"

// The mesh bake against surfaces with known answers (docs/conventions.md §8): a smooth periodic
// ground, domes crossing the tile's edges, a floating disc, open boxes with vertical walls, a tile
// that is not the unit square, the same mesh read from OBJ, binary PLY and a Y-up glTF. Every
// texel away from rims and walls is checked: heights within the tessellation's error, normals
// within a degree, the copies wrapped, misses and overhangs counted exactly, occlusion against a
// brute-force cosine integral over the analytic surface. The random layouts come from a seed that
// changes per run (printed; PX_TEST_SEED=N repeats it).

#include "parallax/meshbake/MeshBake.h"

#include "BakeTiles.h"
#include "parallax/bake/OcclusionBaker.h"

#include <QTemporaryDir>
#include <QtTest>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>

using namespace px;
using test::TileRect;

namespace {

constexpr double kPi = std::numbers::pi;

BakeMesh toBakeMesh(const test::TestMesh& m) {
    return makeBakeMesh(m.positions, m.normals, m.indices, "generated");
}

BakeTile bakeTile(const TileRect& t) {
    return {t.x0, t.y0, t.x1, t.y1};
}

// The centre of sub-sample (a, b) of texel (i, j): image right = +X, image top = +Y.
glm::dvec2 samplePoint(const MeshBakeOptions& o, int i, int j, int a = 0, int b = 0) {
    const int k = o.samples;
    return {o.tile.x0 + (i + (a + 0.5) / k) / o.width * o.tile.width(),
            o.tile.y1 - (j + (b + 0.5) / k) / o.height * o.tile.height()};
}

double bakedZ(const MeshBakeResult& r, int i, int j) {
    return r.range.z0 + r.height.at(i, j) * (r.range.z1 - r.range.z0);
}

glm::dvec3 bakedNormal(const MeshBakeResult& r, int i, int j, bool directx = false) {
    glm::dvec3 n(r.normal.at(i, j, 0), r.normal.at(i, j, 1), r.normal.at(i, j, 2));
    n = n * 2.0 - 1.0;
    if (directx)
        n.y = -n.y;
    return glm::normalize(n);
}

double degreesBetween(glm::dvec3 a, glm::dvec3 b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) *
           180.0 / kPi;
}

struct Dome {
    glm::dvec2 c;
    double r;
    bool copy = false; // moved by a tile
};

// The domes and their copies a bake sees (3 x 3 with repeat).
std::vector<Dome> seen(const std::vector<Dome>& domes, const TileRect& t, WrapMode wrap) {
    std::vector<Dome> out;
    for (const Dome& d : domes) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                if (wrap == WrapMode::Clamp && (dx != 0 || dy != 0))
                    continue;
                out.push_back(
                    {d.c + glm::dvec2(dx * t.width(), dy * t.height()), d.r, dx != 0 || dy != 0});
            }
        }
    }
    return out;
}

Result<MeshBakeResult> bake(const BakeMesh& mesh, const MeshBakeOptions& o) {
    return bakeFromMesh(mesh, o);
}

} // namespace

class MeshBakeTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void periodicGround_data();
    void periodicGround();
    void subSamplesAreBoxAveraged();
    void domesCrossTheEdges_data();
    void domesCrossTheEdges();
    void copiesWrapTheTile();
    void floatingDiscCountsOverhangs();
    void missesAreCountedAndLowest();
    void boxesWithVerticalWalls();
    void sameMeshFromEveryFormat();
    void occlusionMatchesTheCosineIntegral();
    void flatGroundIsUnoccluded();
    void occlusionMatchesTheHeightMapBake();
    void givenRangeMapsAndRefusesClamping();
    void refusesAnEmptyOrDistantTile();
    void cancelsAndReportsProgress();

private:
    unsigned m_seed = 0;
    std::mt19937 random(unsigned salt) const { return std::mt19937(m_seed * 7919u + salt); }
};

void MeshBakeTest::initTestCase() {
    const char* given = std::getenv("PX_TEST_SEED");
    m_seed = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                   : 1u + std::random_device{}() % 100000u;
    qInfo("layout seed %u (PX_TEST_SEED=%u repeats it)", m_seed, m_seed);
}

void MeshBakeTest::periodicGround_data() {
    QTest::addColumn<double>("x0");
    QTest::addColumn<double>("y0");
    QTest::addColumn<double>("x1");
    QTest::addColumn<double>("y1");
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addColumn<bool>("directx");
    QTest::newRow("unit tile") << 0.0 << 0.0 << 1.0 << 1.0 << 64 << 64 << false;
    QTest::newRow("8 x 4 tile off the origin, DirectX green")
        << -3.0 << 2.0 << 5.0 << 6.0 << 64 << 32 << true;
}

// Heights within the tessellation's error and shading normals within a degree at every texel; no
// misses, no overhangs; the height scale is (z1 - z0) / tile width.
void MeshBakeTest::periodicGround() {
    QFETCH(double, x0);
    QFETCH(double, y0);
    QFETCH(double, x1);
    QFETCH(double, y1);
    QFETCH(int, width);
    QFETCH(int, height);
    QFETCH(bool, directx);
    std::mt19937 rng = random(1);
    const TileRect t{x0, y0, x1, y1};
    const double amplitude = std::uniform_real_distribution<double>(0.03, 0.12)(rng) * t.width();
    const double phase = std::uniform_real_distribution<double>(0.0, 2 * kPi)(rng);
    const int n = 160;
    const BakeMesh mesh = toBakeMesh(test::periodicGround(t, n, amplitude, phase));
    MeshBakeOptions o;
    o.tile = bakeTile(t);
    o.width = width;
    o.height = height;
    o.maps = {true, true, false};
    o.green = directx ? NormalGreen::DirectX : NormalGreen::OpenGL;
    Result<MeshBakeResult> r = bake(mesh, o);
    QVERIFY2(r, r ? "" : r.error().message.c_str());
    QCOMPARE(r->misses, std::int64_t{0});
    QCOMPARE(r->overhangs, std::int64_t{0});
    QCOMPARE(r->copies, 9);
    QCOMPARE(r->samples, static_cast<std::int64_t>(width) * height);
    QVERIFY(std::abs(r->heightScale - (r->range.z1 - r->range.z0) / t.width()) < 1e-9);
    // Linear interpolation over cells of side hx, hy: the error is at most
    // (hx^2 |zxx| + 2 hx hy |zxy| + hy^2 |zyy|) / 2.
    const double a = 2 * kPi / t.width(), b = 2 * kPi / t.height();
    const double hx = t.width() / n, hy = t.height() / n;
    const double tolerance = 0.5 * amplitude * std::pow(hx * a + hy * b, 2) + 1e-6 * t.width();
    double worstZ = 0, worstAngle = 0;
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const glm::dvec2 p = samplePoint(o, i, j);
            const double z = test::periodicGroundZ(t, amplitude, phase, p.x, p.y);
            const double dz = std::abs(bakedZ(*r, i, j) - z);
            const double angle =
                degreesBetween(bakedNormal(*r, i, j, directx),
                               test::periodicGroundNormal(t, amplitude, phase, p.x, p.y));
            worstZ = std::max(worstZ, dz);
            worstAngle = std::max(worstAngle, angle);
            if (dz > tolerance || angle > 1.0)
                QFAIL(qPrintable(QString("seed %1, texel (%2, %3): z off by %4 (tolerance %5), "
                                         "normal %6 degrees off")
                                     .arg(m_seed)
                                     .arg(i)
                                     .arg(j)
                                     .arg(dz)
                                     .arg(tolerance)
                                     .arg(angle)));
        }
    }
    qInfo("worst height error %.3g (tolerance %.3g), worst normal %.3f degrees", worstZ, tolerance,
          worstAngle);
}

// K x K sub-samples: the height is the mean of the surface over the sub-sample points.
void MeshBakeTest::subSamplesAreBoxAveraged() {
    std::mt19937 rng = random(2);
    const TileRect t{0, 0, 2, 2};
    const double amplitude = 0.2, phase = std::uniform_real_distribution<double>(0, 2 * kPi)(rng);
    const int n = 300;
    const BakeMesh mesh = toBakeMesh(test::periodicGround(t, n, amplitude, phase));
    MeshBakeOptions o;
    o.tile = bakeTile(t);
    o.width = o.height = 12;
    o.samples = 3;
    Result<MeshBakeResult> r = bake(mesh, o);
    QVERIFY2(r, r ? "" : r.error().message.c_str());
    QCOMPARE(r->samples, std::int64_t{12 * 12 * 9});
    const double a = 2 * kPi / t.width(), h = t.width() / n;
    const double tolerance = 0.5 * amplitude * std::pow(2 * h * a, 2) + 1e-6;
    double worstCentre = 0;
    for (int j = 0; j < o.height; ++j) {
        for (int i = 0; i < o.width; ++i) {
            double mean = 0;
            for (int b = 0; b < 3; ++b) {
                for (int s = 0; s < 3; ++s) {
                    const glm::dvec2 p = samplePoint(o, i, j, s, b);
                    mean += test::periodicGroundZ(t, amplitude, phase, p.x, p.y) / 9;
                }
            }
            const double dz = std::abs(bakedZ(*r, i, j) - mean);
            if (dz > tolerance)
                QFAIL(qPrintable(QString("seed %1, texel (%2, %3): z off the sub-samples' mean "
                                         "by %4 (tolerance %5)")
                                     .arg(m_seed)
                                     .arg(i)
                                     .arg(j)
                                     .arg(dz)
                                     .arg(tolerance)));
            const glm::dvec2 c = samplePoint(o, i, j, 1, 1);
            worstCentre = std::max(
                worstCentre,
                std::abs(bakedZ(*r, i, j) - test::periodicGroundZ(t, amplitude, phase, c.x, c.y)));
        }
    }
    // The mean differs from the centre's value where the surface curves: the test can tell them.
    QVERIFY2(worstCentre > 5 * tolerance,
             qPrintable(QString("the centres would pass too (%1)").arg(worstCentre)));
}

void MeshBakeTest::domesCrossTheEdges_data() {
    QTest::addColumn<int>("wrap");
    QTest::newRow("repeat") << static_cast<int>(WrapMode::Repeat);
    QTest::newRow("clamp") << static_cast<int>(WrapMode::Clamp);
}

// Domes placed across the right edge, the top edge and a corner: with repeat the part beyond an
// edge comes back on the opposite one; with clamp it is gone. Heights and radial normals at every
// texel away from the rims.
void MeshBakeTest::domesCrossTheEdges() {
    QFETCH(int, wrap);
    const auto mode = static_cast<WrapMode>(wrap);
    std::mt19937 rng = random(3);
    std::uniform_real_distribution<double> radius(0.12, 0.22), inside(-0.5, 0.5);
    const TileRect t{0, 0, 1, 1};
    std::vector<Dome> domes;
    domes.push_back({{1.0 + 0.5 * inside(rng) * 0.2, 0.5 + 0.6 * inside(rng)}, radius(rng)});
    domes.push_back({{0.5 + 0.6 * inside(rng), 1.0 + 0.5 * inside(rng) * 0.2}, radius(rng)});
    domes.push_back({{0.0 + 0.04 * inside(rng), 0.0 + 0.04 * inside(rng)}, radius(rng)});
    test::TestMesh m = test::flatGround(t, 8);
    for (const Dome& d : domes)
        test::append(m, test::dome({d.c.x, d.c.y, 0.0}, d.r, 160, 48));
    const BakeMesh mesh = toBakeMesh(m);
    MeshBakeOptions o;
    o.tile = bakeTile(t);
    o.width = o.height = 96;
    o.wrap = mode;
    o.maps = {true, true, false};
    Result<MeshBakeResult> r = bake(mesh, o);
    QVERIFY2(r, r ? "" : r.error().message.c_str());
    QCOMPARE(r->copies, mode == WrapMode::Repeat ? 9 : 1);
    const std::vector<Dome> all = seen(domes, t, mode);
    const double texel = t.width() / o.width;
    // Chords of a sphere cut at most r (1 - cos(step)) below it; near the rim a vertical error
    // grows as the surface steepens: the check stops at 0.9 r.
    const double chord = 1.0 - std::cos(2 * kPi / 160);
    int checked = 0, onDomes = 0, edgeDomes = 0;
    for (int j = 0; j < o.height; ++j) {
        for (int i = 0; i < o.width; ++i) {
            const glm::dvec2 p = samplePoint(o, i, j);
            double z = 0;
            glm::dvec3 n(0, 0, 1);
            bool nearRim = false, copy = false;
            double second = 0; // the next highest surface: near a crease the tops swap
            for (const Dome& d : all) {
                const double dist = glm::length(p - d.c);
                nearRim = nearRim || (dist > 0.9 * d.r && dist < d.r + texel);
                if (dist < d.r) {
                    const double top = std::sqrt(d.r * d.r - dist * dist);
                    second = std::max(second, std::min(top, z));
                    if (top > z) {
                        z = top;
                        n = glm::dvec3(p - d.c, top) / d.r;
                        copy = d.copy;
                    }
                }
            }
            if (nearRim || (second > 0 && z - second < 0.01))
                continue;
            ++checked;
            onDomes += z > 0;
            edgeDomes += copy;
            const double tolerance = 3.0 * chord * 0.22 + 1e-6;
            const double dz = std::abs(bakedZ(*r, i, j) - z);
            const double angle = degreesBetween(bakedNormal(*r, i, j), n);
            if (dz > tolerance || angle > 1.0)
                QFAIL(qPrintable(QString("seed %1, %2, texel (%3, %4): z %5 for %6, normal %7 "
                                         "degrees off")
                                     .arg(m_seed)
                                     .arg(toString(mode).data())
                                     .arg(i)
                                     .arg(j)
                                     .arg(bakedZ(*r, i, j))
                                     .arg(z)
                                     .arg(angle)));
        }
    }
    QVERIFY(checked > o.width * o.height / 2);
    QVERIFY(onDomes > 100);
    // With repeat, texels show the domes' copies moved by a tile; with clamp none.
    QCOMPARE(edgeDomes > 0, mode == WrapMode::Repeat);
}

// The same mesh baked over the tile and over the tile moved by half its width and a quarter of its
// height: with repeat the second is the first turned around the torus, texel for texel.
void MeshBakeTest::copiesWrapTheTile() {
    std::mt19937 rng = random(4);
    const TileRect t{-1, 0, 1, 1};
    test::TestMesh m =
        test::periodicGround(t, 64, 0.1, std::uniform_real_distribution<double>(0, 6)(rng));
    std::uniform_real_distribution<double> across(-1, 1), up(0, 1);
    for (int d = 0; d < 4; ++d)
        test::append(m, test::dome({across(rng), up(rng), 0.05}, 0.2, 48, 16));
    const BakeMesh mesh = toBakeMesh(m);
    MeshBakeOptions o;
    o.tile = bakeTile(t);
    o.width = 64;
    o.height = 32;
    o.maps = {true, true, false};
    o.range = HeightRangeZ{-0.2, 0.3};
    Result<MeshBakeResult> a = bake(mesh, o);
    QVERIFY2(a, a ? "" : a.error().message.c_str());
    const int sx = 32, sy = 8;
    o.tile = {t.x0 + sx * t.width() / o.width, t.y0 - sy * t.height() / o.height,
              t.x1 + sx * t.width() / o.width, t.y1 - sy * t.height() / o.height};
    Result<MeshBakeResult> b = bake(mesh, o);
    QVERIFY2(b, b ? "" : b.error().message.c_str());
    for (int j = 0; j < o.height; ++j) {
        for (int i = 0; i < o.width; ++i) {
            const int ia = (i + sx) % o.width, ja = (j + sy) % o.height;
            const double dz = std::abs(bakedZ(*a, ia, ja) - bakedZ(*b, i, j));
            const double angle = degreesBetween(bakedNormal(*a, ia, ja), bakedNormal(*b, i, j));
            if (dz > 1e-5 || angle > 0.05)
                QFAIL(qPrintable(QString("seed %1: texel (%2, %3) of the moved tile is %4 off "
                                         "(normal %5 degrees) from (%6, %7)")
                                     .arg(m_seed)
                                     .arg(i)
                                     .arg(j)
                                     .arg(dz)
                                     .arg(angle)
                                     .arg(ia)
                                     .arg(ja)));
        }
    }
}

// A disc floating over the ground: its top wins, and every sample inside it (its polygon, tested
// exactly) counts as an overhang; its underside, facing down, is not one.
void MeshBakeTest::floatingDiscCountsOverhangs() {
    std::mt19937 rng = random(5);
    std::uniform_real_distribution<double> at(0.35, 0.65), radius(0.15, 0.3);
    const glm::dvec2 c(at(rng), at(rng));
    const double r = radius(rng), top = 0.4;
    const int sides = 40;
    const TileRect t{0, 0, 1, 1};
    test::TestMesh m = test::flatGround(t, 4);
    test::append(m, test::floatingDisc(c, r, top, 0.05, sides));
    const BakeMesh mesh = toBakeMesh(m);
    for (int k : {1, 2}) {
        MeshBakeOptions o;
        o.tile = bakeTile(t);
        o.width = o.height = 50;
        o.samples = k;
        o.wrap = WrapMode::Clamp;
        o.maps = {true, true, false};
        Result<MeshBakeResult> res = bake(mesh, o);
        QVERIFY2(res, res ? "" : res.error().message.c_str());
        // Inside the polygon: on the inner side of every edge (vertices as the mesh has them).
        auto inside = [&](glm::dvec2 p) {
            for (int s = 0; s < sides; ++s) {
                const double a0 = 2 * kPi * s / sides, a1 = 2 * kPi * (s + 1) / sides;
                const glm::dvec2 v0 =
                    glm::dvec2(glm::vec2(c + r * glm::dvec2(std::cos(a0), std::sin(a0))));
                const glm::dvec2 v1 =
                    glm::dvec2(glm::vec2(c + r * glm::dvec2(std::cos(a1), std::sin(a1))));
                const glm::dvec2 e = v1 - v0, q = p - v0;
                if (e.x * q.y - e.y * q.x <= 0)
                    return false;
            }
            return true;
        };
        std::int64_t expected = 0;
        for (int j = 0; j < o.height; ++j) {
            for (int i = 0; i < o.width; ++i) {
                int in = 0;
                for (int b = 0; b < k; ++b) {
                    for (int a = 0; a < k; ++a)
                        in += inside(samplePoint(o, i, j, a, b));
                }
                expected += in;
                const double want = top * in / (k * k);
                if (std::abs(bakedZ(*res, i, j) - want) > 1e-5)
                    QFAIL(qPrintable(QString("seed %1, K %2, texel (%3, %4): z %5, expected %6")
                                         .arg(m_seed)
                                         .arg(k)
                                         .arg(i)
                                         .arg(j)
                                         .arg(bakedZ(*res, i, j))
                                         .arg(want)));
                if (in == 0 || in == k * k)
                    QVERIFY(degreesBetween(bakedNormal(*res, i, j), {0, 0, 1}) < 0.01);
            }
        }
        QVERIFY(expected > 100);
        QCOMPARE(res->overhangs, expected);
        QCOMPARE(res->misses, std::int64_t{0});
    }
}

// A tile wider than the mesh, clamp: the samples off the mesh miss, are counted, and take the
// range's minimum.
void MeshBakeTest::missesAreCountedAndLowest() {
    std::mt19937 rng = random(6);
    const TileRect ground{0, 0, 1, 1};
    const BakeMesh mesh = toBakeMesh(
        test::periodicGround(ground, 64, 0.1, std::uniform_real_distribution<double>(0, 6)(rng)));
    MeshBakeOptions o;
    o.tile = {-0.25, 0, 1.25, 1}; // texels of 1/32: the mesh's sides fall between centres
    o.width = 48;
    o.height = 32;
    o.samples = 2;
    o.wrap = WrapMode::Clamp;
    Result<MeshBakeResult> r = bake(mesh, o);
    QVERIFY2(r, r ? "" : r.error().message.c_str());
    QCOMPARE(r->misses, std::int64_t{16} * 32 * 4);
    for (int j = 0; j < o.height; ++j) {
        for (int i = 0; i < o.width; ++i) {
            const bool off = i < 8 || i >= 40;
            if (off)
                QCOMPARE(r->height.at(i, j), 0.0f);
            else
                QVERIFY(bakedZ(*r, i, j) >= r->range.z0);
        }
    }
    // The default range is the hits' range: the lowest hit maps to about 0, the highest to 1.
    float lo = 1, hi = 0;
    for (int j = 0; j < o.height; ++j) {
        for (int i = 8; i < 40; ++i) {
            lo = std::min(lo, r->height.at(i, j));
            hi = std::max(hi, r->height.at(i, j));
        }
    }
    QVERIFY(lo < 0.05f && hi > 0.95f);
}

// Open boxes of random sizes and heights, one across the tile's corner: flat tops and ground,
// normals straight up, at every texel a texel away from the walls.
void MeshBakeTest::boxesWithVerticalWalls() {
    std::mt19937 rng = random(7);
    std::uniform_real_distribution<double> at(0.0, 1.0), side(0.1, 0.3), height(0.05, 0.4);
    const TileRect t{0, 0, 1, 1};
    test::TestMesh m = test::flatGround(t, 2);
    std::vector<std::pair<TileRect, double>> boxes;
    for (int b = 0; b < 5; ++b) {
        const double x = b == 0 ? 0.9 : at(rng) * 0.7, y = b == 0 ? 0.85 : at(rng) * 0.7;
        const TileRect r{x, y, x + side(rng), y + side(rng)};
        boxes.emplace_back(r, height(rng));
        test::append(m, test::openBox(r, boxes.back().second));
    }
    const BakeMesh mesh = toBakeMesh(m);
    MeshBakeOptions o;
    o.tile = bakeTile(t);
    o.width = o.height = 64;
    o.maps = {true, true, false};
    Result<MeshBakeResult> r = bake(mesh, o);
    QVERIFY2(r, r ? "" : r.error().message.c_str());
    const double texel = 1.0 / 64;
    int wrapped = 0;
    for (int j = 0; j < o.height; ++j) {
        for (int i = 0; i < o.width; ++i) {
            const glm::dvec2 p = samplePoint(o, i, j);
            double z = 0;
            bool nearWall = false;
            for (const auto& [box, h] : boxes) {
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const double x0 = box.x0 + dx, x1 = box.x1 + dx, y0 = box.y0 + dy,
                                     y1 = box.y1 + dy;
                        const bool in = p.x > x0 && p.x < x1 && p.y > y0 && p.y < y1;
                        const bool outside = p.x < x0 - texel || p.x > x1 + texel ||
                                             p.y < y0 - texel || p.y > y1 + texel;
                        const bool deep = p.x > x0 + texel && p.x < x1 - texel &&
                                          p.y > y0 + texel && p.y < y1 - texel;
                        nearWall = nearWall || (!outside && !deep);
                        if (in && h > z) {
                            z = h;
                            wrapped += (dx != 0 || dy != 0);
                        }
                    }
                }
            }
            if (nearWall)
                continue;
            const double angle = degreesBetween(bakedNormal(*r, i, j), {0, 0, 1});
            if (std::abs(bakedZ(*r, i, j) - z) > 1e-5 || angle > 1e-3)
                QFAIL(qPrintable(QString("seed %1, texel (%2, %3): z %4, expected %5, normal %6 "
                                         "degrees off")
                                     .arg(m_seed)
                                     .arg(i)
                                     .arg(j)
                                     .arg(bakedZ(*r, i, j))
                                     .arg(z)
                                     .arg(angle)));
        }
    }
    QVERIFY(wrapped > 0); // the corner box came back on the other sides
}

// One mesh written as OBJ, binary PLY and a Y-up glTF, read back (--up y for the glTF): the
// bakes agree with the bake of the arrays themselves.
void MeshBakeTest::sameMeshFromEveryFormat() {
    std::mt19937 rng = random(8);
    const TileRect t{0, 0, 2, 1};
    test::TestMesh m =
        test::periodicGround(t, 48, 0.15, std::uniform_real_distribution<double>(0, 6)(rng));
    test::append(m, test::dome({1.9, 0.5, 0.0}, 0.3, 48, 16));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string obj = dir.filePath("tile.obj").toStdString();
    const std::string ply = dir.filePath("tile.ply").toStdString();
    const std::string gltf = dir.filePath("tile.gltf").toStdString();
    QVERIFY(test::writeObj(obj, m));
    QVERIFY(test::writePlyBinary(ply, m));
    QVERIFY(test::writeGltf(gltf, test::toYUp(m)));
    MeshBakeOptions o;
    o.tile = bakeTile(t);
    o.width = 64;
    o.height = 32;
    o.maps = {true, true, false};
    Result<MeshBakeResult> reference = bake(toBakeMesh(m), o);
    QVERIFY2(reference, reference ? "" : reference.error().message.c_str());
    for (const auto& [file, up] :
         {std::pair{obj, MeshUp::Z}, std::pair{ply, MeshUp::Z}, std::pair{gltf, MeshUp::Y}}) {
        BakeMeshLoadOptions load;
        load.up = up;
        Result<BakeMesh> mesh = loadBakeMesh(file, load);
        QVERIFY2(mesh, mesh ? "" : mesh.error().message.c_str());
        QCOMPARE(mesh->triangleCount(), m.indices.size() / 3);
        QVERIFY(!mesh->normals.empty());
        Result<MeshBakeResult> r = bake(*mesh, o);
        QVERIFY2(r, r ? "" : r.error().message.c_str());
        for (int j = 0; j < o.height; ++j) {
            for (int i = 0; i < o.width; ++i) {
                const double dz = std::abs(bakedZ(*r, i, j) - bakedZ(*reference, i, j));
                const double angle =
                    degreesBetween(bakedNormal(*r, i, j), bakedNormal(*reference, i, j));
                if (dz > 1e-5 || angle > 0.05)
                    QFAIL(qPrintable(QString("%1, texel (%2, %3): z %4 off, normal %5 degrees off")
                                         .arg(file.c_str())
                                         .arg(i)
                                         .arg(j)
                                         .arg(dz)
                                         .arg(angle)));
            }
        }
    }
}

namespace {

// (1/pi) * integral over n's hemisphere of V(w) (n . w): V = 0 below the ground plane z = 0 and
// where w meets a dome (spheres centred on the plane), by the midpoint rule on a fine grid.
double cosineIntegral(glm::dvec3 p, glm::dvec3 n, const std::vector<Dome>& domes) {
    const int rings = 192, segments = 384;
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    const glm::dvec3 t(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const glm::dvec3 s(b, sign + n.y * n.y * a, -n.y);
    double sum = 0;
    for (int e = 0; e < rings; ++e) {
        const double elevation = (e + 0.5) / rings * 0.5 * kPi;
        for (int f = 0; f < segments; ++f) {
            const double phi = (f + 0.5) / segments * 2 * kPi;
            const glm::dvec3 w = std::cos(elevation) * (std::cos(phi) * t + std::sin(phi) * s) +
                                 std::sin(elevation) * n;
            bool open = w.z > 0;
            for (const Dome& d : domes) {
                if (!open)
                    break;
                const glm::dvec3 q = p - glm::dvec3(d.c, 0.0);
                const double bq = glm::dot(w, q), c = glm::dot(q, q) - d.r * d.r;
                // Leaving the sphere (c ~ 0, outward) it cannot meet it again.
                open = !(c > 1e-9 && bq < 0 && bq * bq - c > 0);
            }
            // dw = cos(elevation) de dphi about n; weight n . w = sin(elevation).
            sum += open ? std::sin(elevation) * std::cos(elevation) : 0.0;
        }
    }
    return sum * (0.5 * kPi / rings) * (2 * kPi / segments) / kPi;
}

} // namespace

// Occlusion on a dome over the ground (repeat: the copies occlude too) against the cosine
// integral over the analytic surface, at every texel away from the rim.
void MeshBakeTest::occlusionMatchesTheCosineIntegral() {
    std::mt19937 rng = random(9);
    const TileRect t{0, 0, 1, 1};
    const Dome d{{std::uniform_real_distribution<double>(0.3, 0.7)(rng), 0.5},
                 std::uniform_real_distribution<double>(0.15, 0.25)(rng)};
    test::TestMesh m = test::flatGround(t, 4);
    test::append(m, test::dome({d.c.x, d.c.y, 0.0}, d.r, 192, 64));
    MeshBakeOptions o;
    o.tile = bakeTile(t);
    o.width = o.height = 16;
    o.maps = {false, false, true};
    o.rays = 1024;
    o.seed = m_seed;
    Result<MeshBakeResult> r = bake(toBakeMesh(m), o);
    QVERIFY2(r, r ? "" : r.error().message.c_str());
    const std::vector<Dome> all = seen({d}, t, WrapMode::Repeat);
    double worst = 0;
    for (int j = 0; j < o.height; ++j) {
        for (int i = 0; i < o.width; ++i) {
            const glm::dvec2 p = samplePoint(o, i, j);
            const double dist = glm::length(p - d.c);
            if (std::abs(dist - d.r) < 0.1 * d.r)
                continue;
            glm::dvec3 point(p, 0.0), n(0, 0, 1);
            if (dist < d.r) {
                point.z = std::sqrt(d.r * d.r - dist * dist);
                n = (point - glm::dvec3(d.c, 0.0)) / d.r;
            }
            const double want = cosineIntegral(point, n, all);
            const double got = r->occlusion.at(i, j);
            worst = std::max(worst, std::abs(got - want));
            // 1024 stratified rays: the estimate's error is well under 0.5 / sqrt(1024); the
            // worst seen over seeds was 0.006.
            if (std::abs(got - want) > 0.015)
                QFAIL(qPrintable(QString("seed %1, texel (%2, %3): occlusion %4, the integral "
                                         "says %5")
                                     .arg(m_seed)
                                     .arg(i)
                                     .arg(j)
                                     .arg(got)
                                     .arg(want)));
        }
    }
    qInfo("worst occlusion error %.4f", worst);
}

// On a height-field mesh the mesh's occlusion and the height-map occlusion (docs/conventions.md §7)
// of the heights baked from it are one quantity: at every texel they agree within the rays' noise
// and the height map's resolution.
void MeshBakeTest::occlusionMatchesTheHeightMapBake() {
    std::mt19937 rng = random(10);
    const TileRect t{0, 0, 1, 1};
    const double amplitude = std::uniform_real_distribution<double>(0.08, 0.12)(rng);
    const double phase = std::uniform_real_distribution<double>(0, 2 * kPi)(rng);
    const BakeMesh mesh = toBakeMesh(test::periodicGround(t, 192, amplitude, phase));
    MeshBakeOptions o;
    o.tile = bakeTile(t);
    o.width = o.height = 64;
    o.maps = {true, false, true};
    o.rays = 1024;
    o.distance = 0.5; // mesh units = uv units: the tile is 1 wide
    o.seed = m_seed;
    Result<MeshBakeResult> r = bake(mesh, o);
    QVERIFY2(r, r ? "" : r.error().message.c_str());
    HeightField field(o.width, o.height);
    for (int j = 0; j < o.height; ++j) {
        for (int i = 0; i < o.width; ++i)
            field.at(i, j) = r->height.at(i, j);
    }
    OcclusionBakeOptions h;
    h.heightScale = static_cast<float>(r->heightScale);
    h.distance = 0.5;
    h.wrap = WrapMode::Repeat;
    Result<OcclusionMaps> maps = bakeOcclusion(field, h, OcclusionOutputs::AmbientOcclusion);
    QVERIFY2(maps, maps ? "" : maps.error().message.c_str());
    double worst = 0, sum = 0, lowest = 1;
    for (int j = 0; j < o.height; ++j) {
        for (int i = 0; i < o.width; ++i) {
            const double a = r->occlusion.at(i, j), b = maps->occlusion.at(i, j);
            worst = std::max(worst, std::abs(a - b));
            sum += std::abs(a - b);
            lowest = std::min(lowest, b);
            if (std::abs(a - b) > 0.02)
                QFAIL(qPrintable(QString("seed %1, texel (%2, %3): the mesh's occlusion %4, the "
                                         "height map's %5")
                                     .arg(m_seed)
                                     .arg(i)
                                     .arg(j)
                                     .arg(a)
                                     .arg(b)));
        }
    }
    const double mean = sum / (o.width * o.height);
    qInfo("mesh vs height-map occlusion: worst %.4f, mean %.4f, darkest %.3f", worst, mean, lowest);
    QVERIFY(mean < 0.005);
    QVERIFY(lowest < 0.92); // the surface occludes itself: the comparison means something
}

// A plane sees nothing but sky, in both wraps and at every distance.
void MeshBakeTest::flatGroundIsUnoccluded() {
    const BakeMesh mesh = toBakeMesh(test::flatGround({0, 0, 1, 1}, 3, 0.25));
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
        MeshBakeOptions o;
        o.width = o.height = 16;
        o.wrap = wrap;
        o.maps = {true, false, true};
        o.rays = 32;
        Result<MeshBakeResult> r = bake(mesh, o);
        QVERIFY2(r, r ? "" : r.error().message.c_str());
        for (int j = 0; j < 16; ++j) {
            for (int i = 0; i < 16; ++i) {
                QCOMPARE(r->occlusion.at(i, j), 1.0f);
                QCOMPARE(r->height.at(i, j), 1.0f); // a flat range puts every hit on top
            }
        }
        QCOMPARE(r->heightScale, 0.0);
    }
}

// A given range maps z0..z1 to 0..1; a surface outside it is an error naming the mesh, never
// clamped.
void MeshBakeTest::givenRangeMapsAndRefusesClamping() {
    BakeMesh mesh = toBakeMesh(test::flatGround({0, 0, 1, 1}, 3, 0.25));
    mesh.file = "plane.obj";
    MeshBakeOptions o;
    o.width = o.height = 8;
    o.range = HeightRangeZ{0.0, 1.0};
    Result<MeshBakeResult> r = bake(mesh, o);
    QVERIFY2(r, r ? "" : r.error().message.c_str());
    QCOMPARE(r->height.at(3, 3), 0.25f);
    QCOMPARE(r->heightScale, 1.0);
    o.range = HeightRangeZ{0.5, 1.0};
    r = bake(mesh, o);
    QVERIFY(!r);
    QVERIFY2(r.error().message.starts_with("plane.obj: the surface reaches z = 0.25 to 0.25, "
                                           "outside the range 0.5,1"),
             r.error().message.c_str());
}

void MeshBakeTest::refusesAnEmptyOrDistantTile() {
    BakeMesh mesh = toBakeMesh(test::flatGround({0, 0, 1, 1}, 3));
    mesh.file = "plane.obj";
    MeshBakeOptions o;
    o.tile = {2.5, 0, 3.5, 1}; // beyond the copies one tile away
    Result<MeshBakeResult> r = bake(mesh, o);
    QVERIFY(!r);
    QCOMPARE(QString::fromStdString(r.error().message),
             QString("plane.obj: the tile 2.5,0,3.5,1 holds no geometry (the mesh's XY bounds "
                     "are 0,0,1,1)"));
    o.tile = {1.5, 0, 2.5, 1}; // its left neighbour copy reaches into it with repeat
    QVERIFY(bake(mesh, o));
    o.wrap = WrapMode::Clamp;
    QVERIFY(!bake(mesh, o));
    o.tile = {0, 0, 0, 1};
    r = bake(mesh, o);
    QVERIFY(!r);
    QVERIFY(r.error().message.find("is empty") != std::string::npos);
}

void MeshBakeTest::cancelsAndReportsProgress() {
    const BakeMesh mesh = toBakeMesh(test::periodicGround({0, 0, 1, 1}, 32, 0.1, 0.3));
    MeshBakeOptions o;
    o.width = o.height = 256;
    o.maps = {true, true, true};
    o.rays = 8;
    std::vector<float> reported;
    BakeControl control;
    control.progress = [&reported](float done) { reported.push_back(done); };
    QVERIFY(bakeFromMesh(mesh, o, control));
    QVERIFY(!reported.empty());
    QCOMPARE(reported.back(), 1.0f);
    QVERIFY(std::is_sorted(reported.begin(), reported.end()));
    std::atomic<bool> stop{false};
    control.cancel = &stop;
    control.progress = [&stop](float done) {
        if (done > 0.2f)
            stop = true;
    };
    Result<MeshBakeResult> r = bakeFromMesh(mesh, o, control);
    QVERIFY(!r);
    QVERIFY(isCancelled(r.error()));
}

QTEST_GUILESS_MAIN(MeshBakeTest)
#include "MeshBakeTest.moc"

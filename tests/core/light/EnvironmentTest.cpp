// Environments for image-based light: the equirectangular mapping, the built-in sky, loading
// HDR/EXR files with clear errors, and the split-sum pieces checked against direct integration.

#include "parallax/light/Environment.h"

#include "parallax/image/ImageFile.h"
#include "parallax/light/EnvironmentLighting.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QtTest>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

using namespace px;

namespace {

constexpr double kPi = 3.14159265358979323846;

// E(n) / pi summed over every texel of the map in double precision: the reference the nine
// coefficients approximate.
glm::dvec3 directIrradiance(const Image& map, glm::vec3 n) {
    glm::dvec3 sum(0.0);
    for (int y = 0; y < map.height; ++y) {
        const double theta = (y + 0.5) / map.height * kPi;
        const double solidAngle = (2.0 * kPi / map.width) * (kPi / map.height) * std::sin(theta);
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 d =
                equirectDirection({(x + 0.5f) / map.width, (y + 0.5f) / map.height});
            const double cosine = std::max(0.0, double(glm::dot(d, n)));
            sum +=
                glm::dvec3(map.at(x, y, 0), map.at(x, y, 1), map.at(x, y, 2)) * cosine * solidAngle;
        }
    }
    return sum / kPi;
}

// Mean radiance weighted by each texel's solid angle.
double meanRadiance(const Image& img) {
    double sum = 0.0, weight = 0.0;
    for (int y = 0; y < img.height; ++y) {
        const double w = std::sin((y + 0.5) / img.height * kPi);
        for (int x = 0; x < img.width; ++x) {
            sum += w * img.at(x, y, 0);
            weight += w;
        }
    }
    return sum / weight;
}

// The real spherical-harmonic basis, bands 0-2, as EnvironmentLighting.h orders it.
std::array<double, 9> shBasis(glm::dvec3 d) {
    return {0.282095,
            0.488603 * d.y,
            0.488603 * d.z,
            0.488603 * d.x,
            1.092548 * d.x * d.y,
            1.092548 * d.y * d.z,
            0.315392 * (3.0 * d.z * d.z - 1.0),
            1.092548 * d.x * d.z,
            0.546274 * (d.x * d.x - d.y * d.y)};
}

// The nine coefficients of E / pi projected from every texel of the map in double precision:
// what the prefilter computes from its 128-wide copy of the map.
std::array<glm::dvec3, 9> directCoefficients(const Image& map) {
    const double band[9] = {1.0, 2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.25, 0.25, 0.25, 0.25, 0.25};
    std::array<glm::dvec3, 9> sh{};
    for (int y = 0; y < map.height; ++y) {
        const double theta = (y + 0.5) / map.height * kPi;
        const double solidAngle = (2.0 * kPi / map.width) * (kPi / map.height) * std::sin(theta);
        for (int x = 0; x < map.width; ++x) {
            const glm::dvec3 d(
                equirectDirection({(x + 0.5f) / map.width, (y + 0.5f) / map.height}));
            const std::array<double, 9> b = shBasis(d);
            const glm::dvec3 radiance(map.at(x, y, 0), map.at(x, y, 1), map.at(x, y, 2));
            for (int i = 0; i < 9; ++i)
                sh[i] += radiance * (b[i] * solidAngle * band[i]);
        }
    }
    return sh;
}

glm::dvec3 shIrradiance(const std::array<glm::dvec3, 9>& sh, glm::dvec3 n) {
    const std::array<double, 9> b = shBasis(glm::normalize(n));
    glm::dvec3 e(0.0);
    for (int i = 0; i < 9; ++i)
        e += sh[i] * b[i];
    return e;
}

glm::vec3 texel(const Image& img, int x, int y) {
    return {img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)};
}

} // namespace

class EnvironmentTest : public QObject {
    Q_OBJECT

private slots:
    void init() { QVERIFY(m_dir.isValid()); }
    void mappingRoundTrips();
    void constantEnvironmentIsAWhiteFurnace();
    void irradianceMatchesDirectIntegration();
    void anyWidthLightsAsItsTexelsSay();
    void roughnessSpreadsTheSun();
    void splitSumTableIsBounded();
    void skyHasItsSunWhereAsked();
    void loadsEquirectangularFiles();
    void largeFilesShrinkToTwoToOne();
    void greyWithAlphaIsGrey();
    void badFilesAreClearErrors();

private:
    std::string path(const char* name) const { return m_dir.filePath(name).toStdString(); }
    QTemporaryDir m_dir;
};

void EnvironmentTest::mappingRoundTrips() {
    QVERIFY(glm::length(equirectDirection({0.5f, 0.5f}) - glm::vec3(0, 0, 1)) < 1e-6f); // front
    QVERIFY(glm::length(equirectDirection({0.75f, 0.5f}) - glm::vec3(1, 0, 0)) < 1e-6f);
    QVERIFY(equirectDirection({0.3f, 0.0f}).y > 0.9999f); // row 0 is the zenith
    for (float u : {0.1f, 0.37f, 0.8f})
        for (float v : {0.2f, 0.5f, 0.9f})
            QVERIFY(glm::length(equirectUv(equirectDirection({u, v})) - glm::vec2(u, v)) < 1e-5f);
}

// Lit evenly with radiance 1, a white Lambert surface reflects 1 whichever way it faces, and
// prefiltering at any roughness leaves 1.
void EnvironmentTest::constantEnvironmentIsAWhiteFurnace() {
    Image one(128, 64, 3);
    std::fill(one.pixels.begin(), one.pixels.end(), 1.0f);
    const PrefilteredEnvironment env = prefilterEnvironment(one, 64, 4);
    for (glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(0.6f, 0.0f, 0.8f)})
        QVERIFY(glm::length(irradianceAt(env.irradiance, n) - glm::vec3(1.0f)) < 2e-3f);
    QCOMPARE(env.specular.size(), std::size_t(4));
    for (std::size_t level = 0; level < env.specular.size(); ++level) {
        const Image& img = env.specular[level];
        QCOMPARE(img.width, 64 >> level);
        QCOMPARE(img.height, 32 >> level);
        for (float v : img.pixels)
            QVERIFY2(std::abs(v - 1.0f) < 1e-3f,
                     qPrintable(QString("level %1: %2").arg(level).arg(v)));
    }
}

// Nine coefficients hold a smooth function of the normal: against the sum over every texel of
// the built-in sky (sun included), within 3 % of the brightest irradiance.
void EnvironmentTest::irradianceMatchesDirectIntegration() {
    const glm::vec3 sun = glm::normalize(glm::vec3(0.5f, 0.6f, -0.4f));
    const Image sky = makeSkyEnvironment(sun, 256);
    const PrefilteredEnvironment env = prefilterEnvironment(sky, 64, 2);
    const glm::vec3 normals[] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, 1}, sun, -sun};
    double brightest = 0.0, worst = 0.0;
    for (glm::vec3 n : normals)
        brightest = std::max(brightest, glm::length(directIrradiance(sky, n)));
    for (glm::vec3 n : normals) {
        const glm::dvec3 reference = directIrradiance(sky, n);
        const glm::dvec3 sh(irradianceAt(env.irradiance, n));
        worst = std::max(worst, glm::length(sh - reference) / brightest);
    }
    qInfo("irradiance from 9 coefficients within %.2f %% of the brightest", 100.0 * worst);
    QVERIFY(worst < 0.03);
    // Facing the sun gets more light than facing away; the sky above more than the ground.
    QVERIFY(irradianceAt(env.irradiance, sun).x > irradianceAt(env.irradiance, -sun).x);
    QVERIFY(irradianceAt(env.irradiance, {0, 1, 0}).z > irradianceAt(env.irradiance, {0, -1, 0}).z);
}

// Maps of any width light as the sum over their own texels says, not only widths that are a
// multiple of the prefilter's (a 1000-wide map was once cropped to its first 512 columns): white
// over half of the sphere, split across u or v (its irradiance is exactly the nine coefficients'
// bands 0 and 1: against the direct sum), and random bright patches on a dim ground, seeded
// (against the nine coefficients projected from every original texel).
void EnvironmentTest::anyWidthLightsAsItsTexelsSay() {
    std::mt19937 rng(31);
    const glm::vec3 normals[] = {{1, 0, 0},
                                 {-1, 0, 0},
                                 {0, 1, 0},
                                 {0, -1, 0},
                                 {0, 0, 1},
                                 {0, 0, -1},
                                 glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f)),
                                 glm::normalize(glm::vec3(-0.7f, 0.2f, -0.4f))};
    for (int width : {1000, 1500, 1022, 666, 202}) {
        for (const char* kind : {"left half", "top half", "patches"}) {
            Image map(width, width / 2, 3);
            std::uniform_int_distribution<int> cx(0, width - 1), cy(0, width / 2 - 1);
            std::vector<std::pair<int, int>> patches;
            patches.reserve(6);
            for (int k = 0; k < 6; ++k)
                patches.emplace_back(cx(rng), cy(rng));
            for (int y = 0; y < map.height; ++y) {
                for (int x = 0; x < map.width; ++x) {
                    float v = 0.0f;
                    if (kind[0] == 'l')
                        v = 2 * x < map.width ? 1.0f : 0.0f;
                    else if (kind[0] == 't')
                        v = 2 * y < map.height ? 1.0f : 0.0f;
                    else
                        for (auto [px, py] : patches)
                            v += std::abs(x - px) < width / 20 && std::abs(y - py) < width / 40
                                     ? 8.0f
                                     : 0.02f;
                    for (int c = 0; c < 3; ++c)
                        map.at(x, y, c) = v * (1.0f + 0.25f * c);
                }
            }
            const PrefilteredEnvironment env = prefilterEnvironment(map, 256, 2);
            const std::array<glm::dvec3, 9> original = directCoefficients(map);
            double brightest = 0.0, worst = 0.0, worstSh = 0.0;
            for (glm::vec3 n : normals)
                brightest = std::max(brightest, glm::length(shIrradiance(original, n)));
            for (glm::vec3 n : normals) {
                const glm::dvec3 sh(irradianceAt(env.irradiance, n));
                // Against the nine coefficients of the original texels: only the resampling
                // differs (the patches' light is not smooth enough for nine coefficients to
                // hold it to a few percent; the halves' is).
                worstSh =
                    std::max(worstSh, glm::length(sh - shIrradiance(original, n)) / brightest);
                if (kind[0] != 'p')
                    worst = std::max(worst, glm::length(sh - directIrradiance(map, n)) / brightest);
            }
            QVERIFY2(worst < 0.01 && worstSh < 0.005,
                     qPrintable(QString("%1 x %2, %3: irradiance %4 % off, %5 % off the "
                                        "coefficients of every texel")
                                    .arg(width)
                                    .arg(width / 2)
                                    .arg(kind)
                                    .arg(100.0 * worst)
                                    .arg(100.0 * worstSh)));
            // The mirror level keeps the map's light too.
            const double mean = meanRadiance(map), mirror = meanRadiance(env.specular[0]);
            QVERIFY2(std::abs(mirror / mean - 1.0) < 0.01,
                     qPrintable(QString("%1, %2: mirror mean %3 against %4")
                                    .arg(width)
                                    .arg(kind)
                                    .arg(mirror)
                                    .arg(mean)));
        }
    }
}

// Rougher levels spread the sun: its peak falls level by level while the map's mean radiance
// (solid-angle weighted) stays.
void EnvironmentTest::roughnessSpreadsTheSun() {
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.3f, 0.7f, 0.5f));
    const PrefilteredEnvironment env = prefilterEnvironment(makeSkyEnvironment(sun, 512), 128, 5);
    const double mean0 = meanRadiance(env.specular[0]);
    float lastPeak = 1e9f;
    for (std::size_t level = 0; level < env.specular.size(); ++level) {
        const float peak = sampleEquirect(env.specular[level], sun).x;
        QVERIFY2(peak < lastPeak, qPrintable(QString("level %1: sun %2").arg(level).arg(peak)));
        lastPeak = peak;
        if (level > 0) {
            const double m = meanRadiance(env.specular[level]);
            QVERIFY2(
                std::abs(m / mean0 - 1.0) < 0.05,
                qPrintable(QString("level %1: mean %2 against %3").arg(level).arg(m).arg(mean0)));
        }
    }
}

// The table scales and biases F0 of a BRDF that loses no more energy than it has: A, B and A + B
// in [0, 1]; smooth and seen head-on, A + B = 1 (all of the light is reflected); B, Fresnel's
// share, grows at grazing angles.
void EnvironmentTest::splitSumTableIsBounded() {
    const Image table = makeSplitSumTable(16, 256);
    for (int j = 0; j < table.height; ++j) {
        for (int i = 0; i < table.width; ++i) {
            const float a = table.at(i, j, 0), b = table.at(i, j, 1);
            QVERIFY(a >= 0.0f && b >= 0.0f && a + b <= 1.001f);
        }
    }
    QVERIFY(std::abs(table.at(15, 0, 0) + table.at(15, 0, 1) - 1.0f) < 0.02f);
    QVERIFY(table.at(0, 4, 1) > table.at(15, 4, 1));
}

void EnvironmentTest::skyHasItsSunWhereAsked() {
    const glm::vec3 sun = glm::normalize(glm::vec3(0.7f, 0.4f, -0.6f));
    const Image sky = makeSkyEnvironment(sun, 512);
    QCOMPARE(sky.width, 512);
    QCOMPARE(sky.height, 256);
    int bx = 0, by = 0;
    for (int y = 0; y < sky.height; ++y)
        for (int x = 0; x < sky.width; ++x)
            if (sky.at(x, y, 0) > sky.at(bx, by, 0)) {
                bx = x;
                by = y;
            }
    const glm::vec3 brightest =
        equirectDirection({(bx + 0.5f) / sky.width, (by + 0.5f) / sky.height});
    QVERIFY(glm::dot(brightest, sun) > std::cos(1.5f * float(kPi) / 180.0f));
    // A blue sky over a darker ground.
    const glm::vec3 zenith = sampleEquirect(sky, {0, 1, 0}),
                    nadir = sampleEquirect(sky, {0, -1, 0});
    QVERIFY(zenith.z > zenith.x && zenith.z > nadir.z);
}

void EnvironmentTest::loadsEquirectangularFiles() {
    Image map(64, 32, 3);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c)
                map.at(x, y, c) = 0.5f * x + 3.0f * c + 0.01f * y; // over 1: HDR
    ImageWriteOptions exr;
    exr.format = PixelFormat::Float;
    QVERIFY(writeImage(path("sky.exr"), map, exr).ok());
    Result<Image> loaded = loadEnvironment(path("sky.exr"));
    QVERIFY2(loaded.ok(), loaded ? "" : loaded.error().message.c_str());
    QCOMPARE(loaded->width, 64);
    QCOMPARE(loaded->channels, 3);
    QVERIFY(glm::length(texel(*loaded, 40, 7) - texel(map, 40, 7)) < 1e-5f);
    // Grey: every channel the same.
    Image grey(64, 32, 1);
    std::fill(grey.pixels.begin(), grey.pixels.end(), 2.5f);
    QVERIFY(writeImage(path("grey.exr"), grey, exr).ok());
    Result<Image> g = loadEnvironment(path("grey.exr"));
    QVERIFY(g.ok());
    QVERIFY(glm::length(texel(*g, 3, 3) - glm::vec3(2.5f)) < 1e-6f);
    // Radiance HDR too (written by OpenImageIO directly: the project writes no .hdr).
    auto out = OIIO::ImageOutput::create(path("sky.hdr"));
    QVERIFY(out);
    QVERIFY(out->open(path("sky.hdr"), OIIO::ImageSpec(64, 32, 3, OIIO::TypeDesc::FLOAT)));
    QVERIFY(out->write_image(OIIO::TypeDesc::FLOAT, map.pixels.data()));
    QVERIFY(out->close());
    Result<Image> hdr = loadEnvironment(path("sky.hdr"));
    QVERIFY(hdr.ok());
    // RGBE keeps 8 bits of mantissa.
    QVERIFY(glm::length(texel(*hdr, 40, 7) - texel(map, 40, 7)) <
            0.01f * glm::length(texel(map, 40, 7)));
}

// A map over 2048 wide comes down to 2048 x 1024 whatever its width (halving twice took 4100 to
// 1025 x 512), with its light.
void EnvironmentTest::largeFilesShrinkToTwoToOne() {
    Image map(2050, 1025, 3);
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            for (int c = 0; c < 3; ++c)
                map.at(x, y, c) = (x / 7 + y / 5) % 3 == 0 ? 4.0f : 0.5f;
    ImageWriteOptions half;
    half.format = PixelFormat::Half;
    QVERIFY(writeImage(path("wide.exr"), map, half).ok());
    Result<Image> loaded = loadEnvironment(path("wide.exr"));
    QVERIFY(loaded.ok());
    QCOMPARE(loaded->width, 2048);
    QCOMPARE(loaded->height, 1024);
    QVERIFY(std::abs(meanRadiance(*loaded) / meanRadiance(map) - 1.0) < 0.01);
}

// Grey and alpha: the light is grey; alpha is not a colour (it once became green and blue).
void EnvironmentTest::greyWithAlphaIsGrey() {
    Image greyAlpha(64, 32, 2);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 64; ++x) {
            greyAlpha.at(x, y, 0) = 0.25f + 0.01f * x;
            greyAlpha.at(x, y, 1) = 1.0f;
        }
    }
    ImageWriteOptions exr;
    exr.format = PixelFormat::Float;
    QVERIFY(writeImage(path("grey-alpha.exr"), greyAlpha, exr).ok());
    Result<Image> loaded = loadEnvironment(path("grey-alpha.exr"));
    QVERIFY(loaded.ok());
    QCOMPARE(loaded->channels, 3);
    for (int x : {0, 17, 63})
        QVERIFY(glm::length(texel(*loaded, x, 9) - glm::vec3(0.25f + 0.01f * x)) < 1e-6f);
}

void EnvironmentTest::badFilesAreClearErrors() {
    ImageWriteOptions exr;
    exr.format = PixelFormat::Float;
    QVERIFY(writeImage(path("square.exr"), Image(32, 32, 3), exr).ok());
    Image negative(64, 32, 3);
    negative.at(5, 6, 1) = -1.0f;
    QVERIFY(writeImage(path("negative.exr"), negative, exr).ok());
    const std::pair<const char*, const char*> cases[] = {
        {"missing.hdr", "missing.hdr: "},
        {"square.exr", "square.exr: is 32 x 32; an equirectangular environment is twice as wide "
                       "as high"},
        {"negative.exr", "negative.exr: has negative radiance at texel (5, 6)"},
    };
    for (const auto& [name, expected] : cases) {
        Result<Image> r = loadEnvironment(path(name));
        QVERIFY(!r.ok());
        QVERIFY2(QString::fromStdString(r.error().message).contains(expected),
                 r.error().message.c_str());
    }
}

QTEST_APPLESS_MAIN(EnvironmentTest)
#include "EnvironmentTest.moc"

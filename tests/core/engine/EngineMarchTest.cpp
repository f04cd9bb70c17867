// The models of Godot 4's deep parallax (BaseMaterial3D, scene/resources/material.cpp) and Unity
// HDRP's parallax occlusion (PerPixelDisplacement.hlsl) against the published shaders written out
// here step by step in double precision.

#include "parallax/engine/EngineMarch.h"

#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/TraceScene.h"

#include <QtTest>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

using namespace px;

class EngineMarchTest : public QObject {
    Q_OBJECT

private slots:
    void layerCountIsGodotsMix();
    void marchMatchesThePublishedShader();
    void flatMapIsFoundExactly();
    void hdrpStepCountIsItsAngleMix();
    void hdrpMatchesThePublishedShader();
};

namespace {

struct ShaderHit {
    double u, v;
    int fetches;
};

// Godot's fragment code with its uniforms: heightmap_scale is 100 s (Godot multiplies by 0.01),
// view_dir the unit vector towards the eye in tangent space, depth = 1 - height.
ShaderHit publishedShader(const HeightField& field, double u0, double v0, double polarDeg,
                          double azimuthDeg, double heightmapScale, int minLayers, int maxLayers) {
    const double r = std::numbers::pi / 180.0;
    const double vx = -std::sin(polarDeg * r) * std::cos(azimuthDeg * r);
    const double vy = -std::sin(polarDeg * r) * std::sin(azimuthDeg * r);
    const double vz = std::cos(polarDeg * r);
    int fetches = 0;
    auto texture = [&](double u, double v) {
        ++fetches;
        return test::bilinearHeight(field, WrapMode::Repeat, u, v);
    };
    const double a = std::abs(vz); // abs(dot(vec3(0, 0, 1), view_dir))
    const double numLayers = maxLayers * (1.0 - a) + minLayers * a;
    const double layerDepth = 1.0 / numLayers;
    const double px = vx * heightmapScale * 0.01, py = vy * heightmapScale * 0.01;
    const double dx = px / numLayers, dy = py / numLayers;
    double ou = u0, ov = v0;
    double depth = 1.0 - texture(ou, ov);
    double currentDepth = 0.0;
    while (currentDepth < depth) {
        ou -= dx;
        ov -= dy;
        depth = 1.0 - texture(ou, ov);
        currentDepth += layerDepth;
    }
    const double pu = ou + dx, pv = ov + dy;
    const double afterDepth = depth - currentDepth;
    const double beforeDepth = (1.0 - texture(pu, pv)) - currentDepth + layerDepth;
    const double weight = afterDepth / (afterDepth - beforeDepth);
    return {ou * (1.0 - weight) + pu * weight, ov * (1.0 - weight) + pv * weight, fetches};
}

// HDRP Lit's pixel displacement with its uniforms: the view towards the eye in tangent space, the
// amplitude in uv units (s), _PPDMinSamples and _PPDMaxSamples; heights white = top.
ShaderHit publishedHdrp(const HeightField& field, double u0, double v0, double polarDeg,
                        double azimuthDeg, double amplitude, int minSamples, int maxSamples) {
    const double r = std::numbers::pi / 180.0;
    // The eye lies opposite the ray's azimuth (docs/conventions.md §5).
    const double vx = -std::sin(polarDeg * r) * std::cos(azimuthDeg * r);
    const double vy = -std::sin(polarDeg * r) * std::sin(azimuthDeg * r);
    const double vz = std::cos(polarDeg * r);
    // viewDirUV = normalize(float3(viewDirTS.xy * maxHeight, viewDirTS.z))
    const double len =
        std::sqrt(vx * amplitude * vx * amplitude + vy * amplitude * vy * amplitude + vz * vz);
    const double ux = vx * amplitude / len, uy = vy * amplitude / len, uz = vz / len;
    const double unitAngle = std::clamp(std::acos(uz) / (std::numbers::pi / 2), 0.0, 1.0);
    const int numSteps =
        std::min(static_cast<int>(minSamples + (maxSamples - minSamples) * unitAngle), 256);
    int fetches = 0;
    auto height = [&](double ou, double ov) {
        ++fetches;
        return test::bilinearHeight(field, WrapMode::Repeat, u0 + ou, v0 + ov);
    };
    const double stepSize = 1.0 / numSteps;
    const double maxU = ux / -uz, maxV = uy / -uz;                 // parallaxMaxOffsetTS
    const double stepU = stepSize * maxU, stepV = stepSize * maxV; // texOffsetPerStep
    double cu = 0.0, cv = 0.0;
    double prevHeight = height(cu, cv);
    cu += stepU;
    cv += stepV;
    double currHeight = height(cu, cv);
    double rayHeight = 1.0 - stepSize;
    for (int k = 0; k < numSteps; ++k) {
        if (currHeight > rayHeight)
            break;
        prevHeight = currHeight;
        rayHeight -= stepSize;
        cu += stepU;
        cv += stepV;
        currHeight = height(cu, cv);
    }
    double pt0 = rayHeight + stepSize, pt1 = rayHeight;
    double delta0 = pt0 - prevHeight, delta1 = pt1 - currHeight;
    double ou = 0.0, ov = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double intersection = (pt0 * delta1 - pt1 * delta0) / (delta1 - delta0);
        ou = (1.0 - intersection) * stepU * numSteps;
        ov = (1.0 - intersection) * stepV * numSteps;
        currHeight = height(ou, ov);
        const double delta = intersection - currHeight;
        if (std::abs(delta) <= 0.01)
            break;
        if (delta < 0.0) {
            delta1 = delta;
            pt1 = intersection;
        } else {
            delta0 = delta;
            pt0 = intersection;
        }
    }
    return {u0 + ou, v0 + ov, fetches};
}

// An engine model against its shader written out in double on a 64² map: 5 polar angles x 4
// azimuths x 2 settings x 50 random rays, every hit within `texelTolerance` and the same fetches.
// `march(u0, v0, polar, azimuth, setting)` returns (shader hit, model hit).
template <class March>
void compareWithShader(unsigned seed, const std::array<EngineLayers, 2>& settings,
                       double texelTolerance, March march) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    int compared = 0;
    for (double polar : {0.0, 30.0, 60.0, 80.0, 88.0}) {
        for (double azimuth : {0.0, 35.0, 150.0, 260.0}) {
            for (const EngineLayers& setting : settings) {
                for (int k = 0; k < 50; ++k) {
                    const double u0 = uniform(rng), v0 = uniform(rng);
                    const auto [want, got] = march(u0, v0, polar, azimuth, setting);
                    const double texels = std::hypot(got.u - want.u, got.v - want.v) * 64.0;
                    QVERIFY2(texels < texelTolerance,
                             qPrintable(QString("polar %1 azimuth %2: %3 texels")
                                            .arg(polar)
                                            .arg(azimuth)
                                            .arg(texels)));
                    QCOMPARE(got.fetches, want.fetches);
                    ++compared;
                }
            }
        }
    }
    QCOMPARE(compared, 5 * 4 * 2 * 50);
}

} // namespace

void EngineMarchTest::layerCountIsGodotsMix() {
    const EngineLayers layers{8, 32};
    QCOMPARE(godotLayerCount(layers, 1.0f), 8.0f);
    QCOMPARE(godotLayerCount(layers, 0.0f), 32.0f);
    QCOMPARE(godotLayerCount(layers, 0.5f), 20.0f);
    QCOMPARE(godotLayerCount(layers, -0.5f), 20.0f); // |cos|
    // Godot's P is the normalised view vector's xy: s sin(polar), not the relief's s tan(polar).
    const glm::vec2 P = godotParallaxVector(0.05f, 60.0, 0.0);
    QVERIFY(std::abs(P.x - 0.05f * std::sin(60.0f * std::numbers::pi_v<float> / 180.0f)) < 1e-7f);
    QCOMPARE(P.y, 0.0f);
}

void EngineMarchTest::marchMatchesThePublishedShader() {
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 64, 64, 3);
    // float against double: the same steps, within float rounding of a texel
    compareWithShader(
        7, {EngineLayers{8, 32}, EngineLayers{2, 7}}, 1e-3,
        [&](double u0, double v0, double polar, double azimuth, const EngineLayers& layers) {
            const float cosPolar = static_cast<float>(std::cos(polar * std::numbers::pi / 180.0));
            const glm::vec2 P = godotParallaxVector(0.05f, polar, azimuth);
            return std::pair(
                publishedShader(field, u0, v0, polar, azimuth, 5.0, layers.minLayers,
                                layers.maxLayers),
                godotDeepParallax(field, WrapMode::Repeat, {u0, v0}, P, cosPolar, layers));
        });
}

void EngineMarchTest::flatMapIsFoundExactly() {
    // On a plane the linear interpolation between the last two layers is exact: the hit is at
    // depth 1 - h along Godot's P, whatever the layers.
    const HeightField flat(16, 16, 0.25f);
    const glm::vec2 P = godotParallaxVector(0.1f, 70.0, 20.0);
    const float cosPolar = static_cast<float>(std::cos(70.0 * std::numbers::pi / 180.0));
    for (int maxLayers : {4, 9, 32}) {
        const TraceResult hit = godotDeepParallax(flat, WrapMode::Repeat, {0.3, 0.6}, P, cosPolar,
                                                  {std::max(1, maxLayers / 4), maxLayers});
        QVERIFY(std::abs(hit.u - (0.3 + P.x * 0.75)) < 1e-5);
        QVERIFY(std::abs(hit.v - (0.6 + P.y * 0.75)) < 1e-5);
        QVERIFY(std::abs(hit.t - 0.75f) < 1e-4f);
    }
}

void EngineMarchTest::hdrpStepCountIsItsAngleMix() {
    // Straight down: the minimum; the uv-space angle is atan(s tan(polar)), not the polar angle.
    QCOMPARE(hdrpStepCount({5, 15}, {0.0f, 0.0f}), 5);
    const float s = 0.05f;
    const double polar = 80.0 * std::numbers::pi / 180.0;
    const auto P = glm::vec2(static_cast<float>(s * std::tan(polar)), 0.0f);
    const double unitAngle = std::atan(s * std::tan(polar)) / (std::numbers::pi / 2);
    QCOMPARE(hdrpStepCount({5, 15}, P), static_cast<int>(5 + 10 * unitAngle));
    QCOMPARE(hdrpStepCount({5, 15}, P), 6); // a shallow relief at 80 degrees: near the minimum
    QCOMPARE(hdrpStepCount({8, 400}, {1e6f, 0.0f}), 256); // HDRP's own limit
}

void EngineMarchTest::hdrpMatchesThePublishedShader() {
    const HeightField field = makeProceduralMap(ProceduralMap::Stones, 64, 64, 3);
    compareWithShader(
        11, {EngineLayers{5, 15}, EngineLayers{2, 40}}, 2e-3,
        [&](double u0, double v0, double polar, double azimuth, const EngineLayers& steps) {
            const glm::vec2 P = parallaxVector(0.05f, polar, azimuth);
            return std::pair(publishedHdrp(field, u0, v0, polar, azimuth, 0.05, steps.minLayers,
                                           steps.maxLayers),
                             hdrpParallaxOcclusion(field, WrapMode::Repeat, {u0, v0}, P, steps));
        });
}

QTEST_GUILESS_MAIN(EngineMarchTest)
#include "EngineMarchTest.moc"

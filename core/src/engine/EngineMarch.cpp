#include "parallax/engine/EngineMarch.h"

#include "trace/TraceKernel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace px {
namespace {

kernel::TraceKernel heightSampler(const HeightField& field, WrapMode wrap) {
    // The kernels' own bilinear sampling (shaders/trace/common.glsl), which counts the fetches.
    kernel::TraceKernel heights;
    heights.pxMapSize = glm::ivec2(field.width, field.height);
    heights.pxWrapRepeat = wrap == WrapMode::Repeat;
    heights.heightField = &field;
    return heights;
}

} // namespace

float godotLayerCount(const EngineLayers& layers, float cosPolar) {
    const float a = std::abs(cosPolar);
    return static_cast<float>(layers.maxLayers) * (1.0f - a) +
           static_cast<float>(layers.minLayers) * a;
}

glm::vec2 godotParallaxVector(float scale, double polarDeg, double azimuthDeg) {
    const double r = std::numbers::pi / 180.0;
    const double len = scale * std::sin(polarDeg * r);
    return {static_cast<float>(len * std::cos(azimuthDeg * r)),
            static_cast<float>(len * std::sin(azimuthDeg * r))};
}

TraceResult godotDeepParallax(const HeightField& field, WrapMode wrap, glm::dvec2 uv0, glm::vec2 P,
                              float cosPolar, const EngineLayers& layers) {
    kernel::TraceKernel heights = heightSampler(field, wrap);
    auto sample = [&](glm::vec2 uv) { return heights.pxHeight(uv); };
    const float numLayers = godotLayerCount(layers, cosPolar);
    const float layerDepth = 1.0f / numLayers;
    const glm::vec2 delta = P / numLayers;
    // The march runs in the tile's own coordinates, as a shader's uv would (float).
    const glm::vec2 base(static_cast<float>(uv0.x), static_cast<float>(uv0.y));
    glm::vec2 ofs = base;
    float depth = 1.0f - sample(ofs);
    float currentDepth = 0.0f;
    // Godot's loop ends once the layer depth passes the surface (at most ~num_layers + 1 steps;
    // the cap only guards against NaN heights).
    const int cap = static_cast<int>(numLayers) + 2;
    for (int k = 0; currentDepth < depth && k < cap; ++k) {
        ofs += delta; // Godot subtracts view.xy: along the ray
        depth = 1.0f - sample(ofs);
        currentDepth += layerDepth;
    }
    const glm::vec2 prevOfs = ofs - delta;
    const float afterDepth = depth - currentDepth;
    const float beforeDepth = (1.0f - sample(prevOfs)) - currentDepth + layerDepth;
    const float weight = afterDepth / (afterDepth - beforeDepth);
    ofs = ofs * (1.0f - weight) + prevOfs * weight;

    TraceResult r;
    r.u = uv0.x + static_cast<double>(ofs.x - base.x);
    r.v = uv0.y + static_cast<double>(ofs.y - base.y);
    const float len2 = P.x * P.x + P.y * P.y;
    const glm::vec2 d = ofs - base;
    r.t = len2 > 0.0f ? std::clamp((d.x * P.x + d.y * P.y) / len2, 0.0f, 1.0f)
                      : std::clamp(currentDepth, 0.0f, 1.0f);
    r.fetches = heights.pxFetches;
    return r;
}

int hdrpStepCount(const EngineLayers& steps, glm::vec2 P) {
    // acos of normalize(vec3(P, 1)).z is atan |P|
    const float unitAngle = std::clamp(
        std::atan(std::sqrt(P.x * P.x + P.y * P.y)) / (std::numbers::pi_v<float> / 2), 0.0f, 1.0f);
    const float mixed = static_cast<float>(steps.minLayers) +
                        static_cast<float>(steps.maxLayers - steps.minLayers) * unitAngle;
    return std::min(static_cast<int>(mixed), 256);
}

TraceResult hdrpParallaxOcclusion(const HeightField& field, WrapMode wrap, glm::dvec2 uv0,
                                  glm::vec2 P, const EngineLayers& steps) {
    kernel::TraceKernel heights = heightSampler(field, wrap);
    const glm::vec2 base(static_cast<float>(uv0.x), static_cast<float>(uv0.y));
    auto sample = [&](glm::vec2 offset) { return heights.pxHeight(base + offset); };
    const int numSteps = std::max(1, hdrpStepCount(steps, P));
    const float stepSize = 1.0f / static_cast<float>(numSteps);
    const glm::vec2 perStep = P * stepSize;
    // The first step is taken before the loop; the ray starts one step below the top.
    glm::vec2 current(0.0f);
    float prevHeight = sample(current);
    current += perStep;
    float currHeight = sample(current);
    float rayHeight = 1.0f - stepSize;
    for (int k = 0; k < numSteps; ++k) {
        if (currHeight > rayHeight)
            break;
        prevHeight = currHeight;
        rayHeight -= stepSize;
        current += perStep;
        currHeight = sample(current);
    }
    // Secant steps on the segment between the last two heights.
    float pt0 = rayHeight + stepSize;
    float pt1 = rayHeight;
    float delta0 = pt0 - prevHeight;
    float delta1 = pt1 - currHeight;
    glm::vec2 offset(0.0f);
    float intersection = pt1;
    for (int k = 0; k < 3; ++k) {
        intersection = (pt0 * delta1 - pt1 * delta0) / (delta1 - delta0);
        offset = (1.0f - intersection) * perStep * static_cast<float>(numSteps);
        currHeight = sample(offset);
        const float delta = intersection - currHeight;
        if (std::abs(delta) <= 0.01f)
            break;
        if (delta < 0.0f) {
            delta1 = delta;
            pt1 = intersection;
        } else {
            delta0 = delta;
            pt0 = intersection;
        }
    }
    TraceResult r;
    r.u = uv0.x + static_cast<double>(offset.x);
    r.v = uv0.y + static_cast<double>(offset.y);
    r.t = 1.0f - intersection;
    r.fetches = heights.pxFetches;
    return r;
}

} // namespace px

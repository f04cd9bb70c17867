#include "parallax/eval/EngineMarch.h"

#include "ProbeRun.h"
#include "trace/TraceKernel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace px {
namespace {

constexpr int kLayerRungs[] = {4,  5,  6,  7,  8,  9,  10, 11, 12, 14, 16, 18,  20, 22,
                               25, 28, 32, 36, 40, 45, 50, 56, 64, 80, 96, 112, 128};

// The ladder's min/max pair for a max: Godot's 8-32 keep max = 4 min, HDRP's 5-15 max = 3 min.
EngineLayers rung(EngineMarch engine, int maxLayers) {
    const int ratio = engine == EngineMarch::Godot ? 4 : 3;
    return {std::max(1, (maxLayers + ratio / 2) / ratio), maxLayers};
}

const char* engineName(EngineMarch engine) {
    return engine == EngineMarch::Godot ? "Godot deep parallax" : "HDRP parallax occlusion";
}

std::string layersText(EngineMarch engine, const EngineLayers& l) {
    return std::to_string(l.minLayers) + "-" + std::to_string(l.maxLayers) +
           (engine == EngineMarch::Godot ? " layers" : " steps");
}

Probe engineProbe(EngineMarch engine, const EngineLayers& layers, const HeightField& field,
                  WrapMode wrap) {
    Probe probe;
    probe.key = std::string(engine == EngineMarch::Godot ? "godot:" : "hdrp:") +
                std::to_string(layers.minLayers) + "-" + std::to_string(layers.maxLayers);
    // Godot offsets by the normalised view vector; HDRP by the relief's own offset.
    probe.model = engine == EngineMarch::Godot ? RayModel::NormalisedView : RayModel::Relief;
    probe.make = [engine, layers, &field, wrap]() -> Result<RangeTrace> {
        return RangeTrace([engine, layers, &field, wrap](const RaySample& rays, std::size_t begin,
                                                         std::size_t end,
                                                         std::span<TraceResult> hits) {
            const float sinPolar =
                static_cast<float>(std::sin(rays.polarDeg * std::numbers::pi / 180.0));
            const float cosPolar = std::sqrt(std::max(0.0f, 1.0f - sinPolar * sinPolar));
            for (std::size_t k = begin; k < end; ++k)
                hits[k] =
                    engine == EngineMarch::Godot
                        ? godotDeepParallax(field, wrap, rays.uv0[k], rays.P[k], cosPolar, layers)
                        : hdrpParallaxOcclusion(field, wrap, rays.uv0[k], rays.P[k], layers);
        });
    };
    return probe;
}

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

Result<EngineLayersAdvice> recommendEngineLayers(EngineMarch engine, const RecommendConfig& config,
                                                 const std::string& fallback,
                                                 const EvalControl& control) {
    if (Status s = validate(config); !s)
        return s.error();
    ProbeRun run(config, control);
    auto measure = [&](int maxLayers) -> Result<std::vector<AngleMeasure>> {
        Result<ProbeRun::Measured> m = run.measure(
            engineProbe(engine, rung(engine, maxLayers), *config.field, config.wrap), false);
        if (!m)
            return m.error();
        return std::move(m->angles);
    };
    auto meets = [&](const std::vector<AngleMeasure>& angles) {
        return angles.size() == run.polars().size() && angles.back().meets;
    };
    EngineLayersAdvice advice;
    advice.engine = engine;
    const int top = std::size(kLayerRungs) - 1;
    Result<std::vector<AngleMeasure>> best = measure(kLayerRungs[top]);
    if (!best)
        return best.error();
    char budget[96];
    std::snprintf(budget, sizeof budget, "%s <= %g texel up to %g degrees",
                  std::string(budgetMetricName(config.budget.metric)).c_str(), config.budget.texels,
                  config.maxPolarDeg);
    if (!meets(*best)) {
        advice.tried = rung(engine, kLayerRungs[top]);
        advice.angles = *best;
        const AngleMeasure& failed = best->back();
        char text[320];
        std::snprintf(
            text, sizeof text,
            "%s does not meet %s with up to %s: at %g degrees its p99 error is %.3g texels "
            "(upper bound %.3g), its worst ray %.3g",
            engine == EngineMarch::Godot ? "Godot's deep parallax" : "HDRP's parallax occlusion",
            budget, layersText(engine, advice.tried).c_str(), failed.polarDeg, failed.p99,
            failed.p99Bound, failed.maxError);
        advice.note = text;
        if (!fallback.empty())
            advice.note += "; " + fallback + " does";
        return advice;
    }
    int lo = 0, hi = top;
    std::vector<AngleMeasure> chosen = *best;
    while (lo < hi) {
        const int mid = lo + (hi - lo) / 2;
        Result<std::vector<AngleMeasure>> at = measure(kLayerRungs[mid]);
        if (!at)
            return at.error();
        if (meets(*at)) {
            hi = mid;
            chosen = *at;
        } else {
            lo = mid + 1;
        }
    }
    advice.found = true;
    advice.layers = rung(engine, kLayerRungs[hi]);
    advice.angles = chosen;
    advice.note = std::string(engineName(engine)) + " with " + layersText(engine, advice.layers) +
                  " (its own march, modelled): the fewest that meet " + budget;
    return advice;
}

} // namespace px

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

EngineLayers rung(int maxLayers) {
    return {std::max(1, (maxLayers + 2) / 4), maxLayers};
}

Probe godotProbe(const EngineLayers& layers, const HeightField& field, WrapMode wrap, float scale) {
    Probe probe;
    probe.key =
        "godot:" + std::to_string(layers.minLayers) + "-" + std::to_string(layers.maxLayers);
    probe.model = RayModel::NormalisedView;
    probe.make = [layers, &field, wrap, scale]() -> Result<RangeTrace> {
        return RangeTrace([layers, &field, wrap, scale](const RaySample& rays, std::size_t begin,
                                                        std::size_t end,
                                                        std::span<TraceResult> hits) {
            const float sinPolar =
                static_cast<float>(std::sin(rays.polarDeg * std::numbers::pi / 180.0));
            const float cosPolar = std::sqrt(std::max(0.0f, 1.0f - sinPolar * sinPolar));
            (void)scale;
            for (std::size_t k = begin; k < end; ++k)
                hits[k] = godotDeepParallax(field, wrap, rays.uv0[k], rays.P[k], cosPolar, layers);
        });
    };
    return probe;
}

std::string layersText(const EngineLayers& l) {
    return std::to_string(l.minLayers) + "-" + std::to_string(l.maxLayers) + " layers";
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
    // The kernels' own bilinear sampling (shaders/trace/common.glsl), which counts the fetches.
    kernel::TraceKernel heights;
    heights.pxMapSize = glm::ivec2(field.width, field.height);
    heights.pxWrapRepeat = wrap == WrapMode::Repeat;
    heights.heightField = &field;
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

Result<EngineLayersAdvice> recommendGodotLayers(const RecommendConfig& config,
                                                const std::string& fallback,
                                                const EvalControl& control) {
    if (Status s = validate(config); !s)
        return s.error();
    ProbeRun run(config, control);
    auto measure = [&](int maxLayers) {
        return run.measure(godotProbe(rung(maxLayers), *config.field, config.wrap, config.scale),
                           false);
    };
    auto meets = [&](const std::vector<AngleMeasure>& angles) {
        return angles.size() == run.polars().size() && angles.back().meets;
    };
    EngineLayersAdvice advice;
    const int top = std::size(kLayerRungs) - 1;
    Result<std::vector<AngleMeasure>> best = measure(kLayerRungs[top]);
    if (!best)
        return best.error();
    char budget[96];
    std::snprintf(budget, sizeof budget, "%s <= %g texel up to %g degrees",
                  std::string(budgetMetricName(config.budget.metric)).c_str(), config.budget.texels,
                  config.maxPolarDeg);
    if (!meets(*best)) {
        advice.tried = rung(kLayerRungs[top]);
        advice.angles = *best;
        const AngleMeasure& failed = best->back();
        char text[256];
        std::snprintf(text, sizeof text,
                      "Godot's deep parallax does not meet %s with up to %s: at %g degrees its "
                      "p99 error is %.3g texels",
                      budget, layersText(advice.tried).c_str(), failed.polarDeg, failed.p99);
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
    advice.layers = rung(kLayerRungs[hi]);
    advice.angles = chosen;
    advice.note = "Godot deep parallax with " + layersText(advice.layers) +
                  " (its own march, modelled): the fewest that meet " + budget;
    return advice;
}

} // namespace px

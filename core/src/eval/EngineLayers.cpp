#include "parallax/eval/EngineLayers.h"

#include "ProbeRun.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace px {
namespace {

// About 12% apart, up to what both engines take (kEngineMaxLayers).
constexpr int kLayerRungs[] = {4,  5,  6,  7,  8,  9,  10, 11, 12, 14, 16, 18,
                               20, 22, 25, 28, 32, 36, 40, 45, 50, 56, 64};
static_assert(kLayerRungs[std::size(kLayerRungs) - 1] == kEngineMaxLayers);

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

} // namespace

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
        char text[384];
        std::snprintf(text, sizeof text,
                      "%s does not meet %s with up to %s (%s takes at most %d): at %g degrees its "
                      "p99 error is %.3g texels (upper bound %.3g), its worst ray %.3g",
                      engine == EngineMarch::Godot ? "Godot's deep parallax"
                                                   : "HDRP's parallax occlusion",
                      budget, layersText(engine, advice.tried).c_str(),
                      engine == EngineMarch::Godot ? "Godot" : "HDRP Lit", kEngineMaxLayers,
                      failed.polarDeg, failed.p99, failed.p99Bound, failed.maxError);
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

#include "parallax/eval/AutoTechnique.h"

#include <cstdio>

namespace px {

MapSet withAutoInputs(const Material& material, MapSet used) {
    const MapSet present = mapsPresent(material.maps);
    used.height = true;
    used.cone = used.cone || present.cone;
    used.relaxedCone = used.relaxedCone || present.relaxedCone;
    return used;
}

Result<ResolvedAuto> resolveAutoTechnique(const Material& material, const HeightField& height,
                                          const ConeMap& cone, const ConeMap& relaxedCone,
                                          const std::string& source,
                                          std::optional<EngineMarch> engine,
                                          const std::string& coneCacheDir) {
    ResolvedAuto resolved{material, {}, std::nullopt, std::nullopt};
    if (!material.autoQuality)
        return resolved;
    if (height.empty())
        return fileError(source, "technique auto needs the height map to measure");
    RecommendConfig config;
    config.field = std::make_shared<HeightField>(height);
    config.name = source;
    config.wrap = material.wrap;
    config.scale = material.heightScale;
    config.cacheDir = coneCacheDir;
    config.maxPolarDeg = material.autoQuality->maxPolar;
    config.budget.texels = material.autoQuality->budgetTexels();
    if (!cone.sqrtRatio.empty())
        config.cone = std::make_shared<ConeMap>(cone);
    if (!relaxedCone.sqrtRatio.empty())
        config.relaxedCone = std::make_shared<ConeMap>(relaxedCone);
    Result<Recommendation> r = recommend(config);
    if (!r)
        return r.error();
    if (!r->found)
        return fileError(source, "technique auto: " + describe(*r, config));
    resolved.material.technique = r->chosen.setting.technique;
    resolved.material.params = r->chosen.setting.params;
    resolved.material.autoQuality.reset();
    const BenchSetting& s = r->chosen.setting;
    char cost[64];
    std::snprintf(cost, sizeof cost, "%.3g fetches per ray", r->chosen.cost);
    char budget[160];
    const AutoQuality& q = *material.autoQuality;
    if (q.budgetPixels && q.texelsPerPixel)
        std::snprintf(budget, sizeof budget,
                      "p99 <= %g texel (%g pixel at %g texels per pixel) up to %g degrees",
                      config.budget.texels, *q.budgetPixels, *q.texelsPerPixel, config.maxPolarDeg);
    else
        std::snprintf(budget, sizeof budget, "p99 <= %g texel up to %g degrees",
                      config.budget.texels, config.maxPolarDeg);
    resolved.note = "technique auto resolved to " + std::string(info(s.technique).name) +
                    (s.label.empty() ? "" : " (" + s.label + ")") + ": the cheapest setting " +
                    "meeting " + budget + ", " + cost;
    resolved.recommendation = *r;
    if (engine) {
        Result<EngineLayersAdvice> layers = recommendEngineLayers(
            *engine, config,
            std::string(info(s.technique).name) +
                (s.label.empty() ? "" : " (" + s.label + ", in the package's shader)"));
        if (!layers)
            return layers.error();
        resolved.engineLayers = std::move(*layers);
    }
    return resolved;
}

} // namespace px

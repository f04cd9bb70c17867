// parallax-cli recommend: the cheapest technique setting that keeps a material within an error
// budget at every view angle up to a maximum (parallax/eval/Recommendation.h), and the Godot
// layer counts that do the same.

#include "Cli.h"
#include "CommonOptions.h"
#include "ProgressLine.h"
#include "parallax/eval/EngineLayers.h"
#include "parallax/eval/QualitySweep.h"
#include "parallax/eval/Recommendation.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/material/MaterialAssets.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/render/GpuConeBaker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace px::cli {

namespace {

struct RecommendOptions {
    std::string material;
    HeightOptions height;
    std::optional<float> scale;
    double maxPolar = 80.0;
    std::optional<double> budget;
    std::optional<double> budgetPixels;
    std::optional<double> texelsPerPixel;
    std::optional<double> viewDistance;
    double fov = 60.0;
    int screenHeight = 1080;
    double surfaceWidth = 1.0;
    std::string metric = "p99";
    std::string cost = "fetches";
    std::string techniques;
    int rays = 32;
    bool godot = false;
    bool hdrp = false;
    bool json = false;
    std::string out = "-";
    ConeCacheOptions cache;
    bool bakeGpu = false;
};

std::string num(double value, const char* pattern = "%.4g") {
    if (!std::isfinite(value))
        return "null";
    char text[48];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string quoted(const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\')
            q += '\\';
        q += c;
    }
    return q + "\"";
}

std::string settingJson(const BenchSetting& s) {
    const TraceParams& p = s.params;
    const TechniqueInfo& t = info(s.technique);
    std::string j = "{\"name\": " + quoted(std::string(t.name));
    if (t.usesLayers)
        j += ", \"minLayers\": " + std::to_string(p.minLayers) +
             ", \"maxLayers\": " + std::to_string(p.maxLayers);
    if (t.usesBinarySteps)
        j += ", \"binarySteps\": " + std::to_string(p.binarySteps);
    if (t.usesSecantSteps)
        j += ", \"secantSteps\": " + std::to_string(p.secantSteps);
    if (t.usesMaxSteps)
        j += ", \"maxSteps\": " + std::to_string(p.maxSteps);
    return j + "}";
}

std::string anglesJson(const std::vector<AngleMeasure>& angles) {
    std::string j = "[";
    for (const AngleMeasure& a : angles) {
        j += std::string(j.size() > 1 ? ", " : "") + "{\"polar\": " + num(a.polarDeg) +
             ", \"rays\": " + std::to_string(a.rays) + ", \"p99\": " + num(a.p99) +
             ", \"p99Bound\": " + num(a.p99Bound) + ", \"max\": " + num(a.maxError) +
             ", \"wrongSurface\": " + std::to_string(a.wrongSurface) +
             ", \"meanFetches\": " + num(a.meanFetches) +
             (a.cpuNsPerRay ? ", \"cpuNsPerRay\": " + num(*a.cpuNsPerRay) : "") +
             ", \"meets\": " + (a.meets ? "true" : "false") + "}";
    }
    return j + "]";
}

std::string toJson(const Recommendation& r, const RecommendConfig& c,
                   const std::vector<EngineLayersAdvice>& engines) {
    std::ostringstream j;
    j << "{\n  \"found\": " << (r.found ? "true" : "false")
      << ",\n  \"budget\": {\"texels\": " << num(c.budget.texels)
      << ", \"metric\": " << quoted(std::string(budgetMetricName(c.budget.metric)))
      << ", \"maxPolar\": " << num(c.maxPolarDeg)
      << "},\n  \"cost\": " << quoted(std::string(costMeasureName(c.cost))) << ",\n";
    if (r.found) {
        j << "  \"technique\": " << settingJson(r.chosen.setting)
          << ",\n  \"costValue\": " << num(r.chosen.cost)
          << ",\n  \"onFront\": " << (r.chosen.onFront ? "true" : "false")
          << ",\n  \"angles\": " << anglesJson(r.chosen.angles) << ",\n  \"maps\": [";
        for (std::size_t k = 0; k < r.maps.size(); ++k)
            j << (k ? ", " : "") << quoted(r.maps[k]);
        j << "],\n";
    }
    j << "  \"measured\": [";
    for (std::size_t k = 0; k < r.measured.size(); ++k) {
        const MeasuredSetting& m = r.measured[k];
        j << (k ? ",\n    " : "\n    ") << "{\"technique\": " << settingJson(m.setting)
          << ", \"meets\": " << (m.meets ? "true" : "false")
          << ", \"dearer\": " << (m.dearer ? "true" : "false")
          << ", \"onFront\": " << (m.onFront ? "true" : "false")
          << ", \"angles\": " << anglesJson(m.angles) << "}";
    }
    j << "],\n  \"confidence\": " << quoted(r.confidence)
      << ",\n  \"raysPerAngle\": " << r.raysPerAngle
      << ",\n  \"coneMaps\": {\"baked\": " << r.mapsBaked << ", \"read\": " << r.mapsFromDisk
      << ", \"cache\": " << quoted(c.cacheDir) << ", \"notKept\": " << quoted(r.cacheProblem)
      << "}";
    for (const EngineLayersAdvice& e : engines) {
        j << ",\n  " << quoted(e.engine == EngineMarch::Godot ? "godot" : "hdrp")
          << ": {\"found\": " << (e.found ? "true" : "false");
        const EngineLayers& l = e.found ? e.layers : e.tried;
        j << ", \"minLayers\": " << l.minLayers << ", \"maxLayers\": " << l.maxLayers
          << ", \"angles\": " << anglesJson(e.angles) << ", \"note\": " << quoted(e.note) << "}";
    }
    j << "\n}\n";
    return j.str();
}

std::string toText(const Recommendation& r, const RecommendConfig& c,
                   const std::vector<EngineLayersAdvice>& engines) {
    std::ostringstream t;
    t << describe(r, c) << "\n";
    if (r.found) {
        t << "  polar   p99 err  p99 bound  max err  fetches/ray\n";
        for (const AngleMeasure& a : r.chosen.angles) {
            char line[96];
            std::snprintf(line, sizeof line, "  %5.1f  %8.3g  %9.3g  %7.3g  %11.2f\n", a.polarDeg,
                          a.p99, a.p99Bound, a.maxError, a.meanFetches);
            t << line;
        }
        t << "  maps it reads: ";
        for (std::size_t k = 0; k < r.maps.size(); ++k)
            t << (k ? ", " : "") << r.maps[k];
        t << "\n  Pareto front (error against fetches at " << num(r.polarDeg.front())
          << " degrees): " << (r.chosen.onFront ? "the choice is on it" : "the choice is not on it")
          << ", " << r.measured.size() << " settings measured";
        const auto dearer = std::count_if(r.measured.begin(), r.measured.end(),
                                          [](const MeasuredSetting& m) { return m.dearer; });
        if (dearer > 0)
            t << " (" << dearer << " of them given up once dearer than a setting that meets)";
        t << "\n";
    }
    t << "  confidence: " << r.confidence << "\n";
    for (const EngineLayersAdvice& e : engines)
        t << "  " << e.note << "\n";
    if (!c.cacheDir.empty() && r.mapsBaked + r.mapsFromDisk > 0) {
        t << "  cone maps: " << r.mapsBaked << " baked, " << r.mapsFromDisk << " read from "
          << c.cacheDir;
        if (!r.cacheProblem.empty())
            t << "; the baked ones were not kept (" << r.cacheProblem << ")";
        t << "\n";
    }
    return t.str();
}

int runRecommend(const RecommendOptions& o) {
    if (o.material.empty() == o.height.file.empty())
        return fail("give exactly one of --material FILE.json or --height FILE");
    if (o.budget && o.budgetPixels)
        return fail(
            "give the budget in texels (--budget) or in pixels (--budget-pixels), not both");
    RecommendConfig config;
    config.cacheDir = o.cache.folder();
    config.maxPolarDeg = o.maxPolar;
    config.raysPerSide = o.rays;
    config.budget.metric = *parseBudgetMetric(o.metric);
    config.cost = *parseCostMeasure(o.cost);
    config.gpuUnavailable = "recommend measures fetches and CPU time; time its choice with "
                            "'parallax-cli bench --gpu'";
    if (o.bakeGpu) {
        // The same kernels on the GPU; no context is an error, as for bake --gpu.
        config.coneBaker = [](const HeightField& f, WrapMode w, ConeKind k,
                              const BakeControl& c) -> Result<ConeMap> {
            Result<ConeMap> gpu = bakeConeMapHeadless(f, w, k, c);
            if (!gpu && !isCancelled(gpu.error()))
                return Error{"--bake-gpu: " + gpu.error().message};
            return gpu;
        };
    }
    double tiling = 1.0;
    int mapWidth = 0;
    if (!o.material.empty()) {
        Result<Material> m = loadMaterial(o.material);
        if (!m)
            return fail(m.error().message);
        MapSet which;
        which.height = true;
        which.cone = true;
        which.relaxedCone = true;
        Result<MaterialAssets> assets = loadMaterialAssets(*m, o.material, which);
        if (!assets)
            return fail(assets.error().message);
        config.name = o.material;
        config.scale = o.scale.value_or(m->heightScale);
        config.wrap = m->wrap;
        tiling = m->tiling;
        mapWidth = assets->height.width;
        config.field = std::make_shared<HeightField>(std::move(assets->height));
        if (!assets->cone.sqrtRatio.empty())
            config.cone = std::make_shared<ConeMap>(std::move(assets->cone));
        if (!assets->relaxedCone.sqrtRatio.empty())
            config.relaxedCone = std::make_shared<ConeMap>(std::move(assets->relaxedCone));
    } else {
        Result<HeightField> field = o.height.load();
        if (!field)
            return fail(field.error().message);
        config.name = o.height.file;
        config.scale = o.scale.value_or(0.05f);
        config.wrap = o.height.wrapMode();
        mapWidth = field->width;
        config.field = std::make_shared<HeightField>(std::move(*field));
    }
    config.budget.texels = o.budget.value_or(0.5);
    if (o.budgetPixels) {
        double tpp = 0.0;
        if (o.texelsPerPixel) {
            tpp = *o.texelsPerPixel;
        } else if (o.viewDistance) {
            ScreenDensity d{mapWidth,        tiling, o.surfaceWidth,
                            *o.viewDistance, o.fov,  o.screenHeight};
            Result<double> density = texelsPerPixel(d);
            if (!density)
                return fail(density.error().message);
            tpp = *density;
        } else {
            return fail("--budget-pixels needs the texel density: --texels-per-pixel T, or "
                        "--view-distance D (with --fov, --screen-height, --surface-width)");
        }
        config.budget.texels = *o.budgetPixels * tpp;
    }
    if (!o.techniques.empty()) {
        Result<std::vector<Technique>> list = parseTechniqueList(o.techniques);
        if (!list)
            return fail(list.error().message);
        config.techniques = std::move(*list);
    }

    // A first run on a map bakes its cone maps (seconds to a minute at 2048²): say so.
    std::unique_ptr<ProgressLine> line;
    std::string lineStage;
    EvalControl control;
    control.progress = [&](const EvalProgress& p) {
        if (!line || p.stage != lineStage) {
            line.reset();
            lineStage = p.stage;
            line = std::make_unique<ProgressLine>(
                p.stage + " of " + config.name +
                (config.cacheDir.empty() ? "" : " (not in the cache " + config.cacheDir + " yet)"));
        }
        (*line)(static_cast<float>(p.done) / static_cast<float>(p.total));
    };
    Result<Recommendation> r = recommend(config, control);
    line.reset();
    if (!r)
        return fail(r.error().message);
    std::vector<EngineLayersAdvice> engines;
    const std::string fallback =
        r->found ? std::string(info(r->chosen.setting.technique).name) +
                       (r->chosen.setting.label.empty() ? "" : " (" + r->chosen.setting.label + ")")
                 : std::string();
    for (auto [asked, engine] :
         {std::pair{o.godot, EngineMarch::Godot}, std::pair{o.hdrp, EngineMarch::Hdrp}}) {
        if (!asked)
            continue;
        Result<EngineLayersAdvice> advice = recommendEngineLayers(engine, config, fallback);
        if (!advice)
            return fail(advice.error().message);
        engines.push_back(std::move(*advice));
    }
    const std::string report = o.json ? toJson(*r, config, engines) : toText(*r, config, engines);
    if (o.out == "-")
        std::cout << report;
    else if (Status s = writeTextFile(o.out, report); !s)
        return fail(s.error().message);
    if (!r->found)
        return fail("nothing meets the budget: allow more techniques, or a larger budget");
    return 0;
}

} // namespace

Action addRecommendCommand(CLI::App& app) {
    auto o = std::make_shared<RecommendOptions>();
    CLI::App* cmd = app.add_subcommand(
        "recommend", "Pick the cheapest technique setting that stays within an error budget at "
                     "every view angle up to a maximum");
    cmd->add_option("--material", o->material, "Material file (.json)");
    o->height.addTo(*cmd, false);
    cmd->add_option("--scale", o->scale,
                    "Height scale s in uv units (default: the material's, or 0.05)")
        ->check(inRange(0.0, 100.0));
    cmd->add_option("--max-polar", o->maxPolar, "Steepest view angle from the normal, degrees")
        ->check(inRange(0.0, 89.0));
    cmd->add_option("--budget", o->budget, "Error budget in texels of the map (default 0.5)")
        ->check(inRange(0.0, 1e6));
    cmd->add_option("--budget-pixels", o->budgetPixels, "Error budget in screen pixels")
        ->check(inRange(0.0, 1e6));
    cmd->add_option("--texels-per-pixel", o->texelsPerPixel,
                    "With --budget-pixels: texels of the map per screen pixel")
        ->check(positive());
    cmd->add_option("--view-distance", o->viewDistance,
                    "With --budget-pixels: distance to the surface, in the surface's units");
    cmd->add_option("--fov", o->fov, "Vertical field of view, degrees (default 60)");
    cmd->add_option("--screen-height", o->screenHeight, "Screen height in pixels (default 1080)");
    cmd->add_option("--surface-width", o->surfaceWidth,
                    "Width the material's tiles span, in the surface's units (default 1)");
    cmd->add_option("--metric", o->metric,
                    "Budget on: p99 (default), max, surface (p99 and no "
                    "ray on another surface)")
        ->check(CLI::IsMember({"p99", "max", "surface"}));
    cmd->add_option("--cost", o->cost, "Cost to minimise: fetches (default, exact), cpu, gpu")
        ->check(CLI::IsMember({"fetches", "cpu", "gpu"}));
    cmd->add_option("--techniques", o->techniques, "Techniques to choose from (default: all)");
    cmd->add_option("--rays", o->rays, "Jittered rays per side per azimuth (default 32)")
        ->check(inRange(4, 256));
    cmd->add_flag("--godot", o->godot, "Also the fewest Godot deep-parallax layers that meet it");
    cmd->add_flag("--hdrp", o->hdrp,
                  "Also the fewest Unity HDRP parallax-occlusion steps that meet it");
    o->cache.addTo(*cmd);
    cmd->add_flag("--bake-gpu", o->bakeGpu,
                  "Bake the cone maps it needs on the GPU (the same maps; an error where no "
                  "OpenGL 4.3 context can be made)");
    cmd->add_flag("--json", o->json, "Write JSON instead of text");
    cmd->add_option("--out", o->out, "Output file (default: standard output)");
    return [o] { return runRecommend(*o); };
}

} // namespace px::cli

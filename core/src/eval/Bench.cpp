#include "parallax/eval/Bench.h"

#include "RayBatch.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/trace/TraceScene.h"

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstdio>

namespace px {
namespace {

// bakeConeMap() is gaining a BakeControl and a Result (the fast bakers); until it has, the slow
// baker runs uncancelled. Templated so the branch not taken is never compiled.
template <typename Field>
Result<ConeMap> bakeCones(const Field& field, WrapMode wrap, ConeKind kind,
                          const BakeControl& control) {
    if constexpr (requires {
                      { bakeConeMap(field, wrap, kind, control) } -> std::same_as<Result<ConeMap>>;
                  })
        return bakeConeMap(field, wrap, kind, control);
    else
        return bakeConeMap(field, wrap, kind);
}

// The derived maps of one height field, baked once for every setting that reads them.
struct PreparedMap {
    const BenchMap* source = nullptr;
    std::shared_ptr<const ConeMap> cone;
    std::shared_ptr<const ConeMap> relaxedCone;
    std::shared_ptr<const MaxMipPyramid> pyramid;

    TraceMaps maps(WrapMode wrap) const {
        TraceMaps m;
        m.height = source->field.get();
        m.wrap = wrap;
        m.cone = cone.get();
        m.relaxedCone = relaxedCone.get();
        m.pyramid = pyramid.get();
        return m;
    }
};

std::string formatAngle(double degrees) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", degrees);
    return text;
}

class BenchRun {
public:
    BenchRun(const BenchConfig& config, const EvalControl& control)
        : m_config(config), m_control(control) {}

    Result<BenchReport> run();

private:
    bool needs(bool TechniqueInfo::*flag) const {
        return std::any_of(m_config.settings.begin(), m_config.settings.end(),
                           [&](const BenchSetting& s) { return info(s.technique).*flag; });
    }
    void step(const std::string& stage) {
        ++m_progressState.done;
        m_progressState.stage = stage;
        if (m_control.progress)
            m_control.progress(m_progressState);
    }
    bool stopped() const { return m_control.cancelled(); }
    Status prepareMaps();
    Status tracePolar(double polar, BenchReport& report);

    const BenchConfig& m_config;
    const EvalControl& m_control;
    EvalProgress m_progressState;
    std::vector<PreparedMap> m_prepared;
};

Status BenchRun::prepareMaps() {
    const BakeControl bakeControl{{}, m_control.cancel};
    for (const BenchMap& map : m_config.maps) {
        PreparedMap p;
        p.source = &map;
        const HeightField& field = *map.field;
        for (ConeKind kind : {ConeKind::Conservative, ConeKind::Relaxed}) {
            const bool conservative = kind == ConeKind::Conservative;
            if (!needs(conservative ? &TechniqueInfo::needsConeMap
                                    : &TechniqueInfo::needsRelaxedConeMap))
                continue;
            if (stopped())
                return evaluationCancelled();
            Result<ConeMap> cones = bakeCones(field, m_config.wrap, kind, bakeControl);
            if (!cones)
                return isCancelled(cones.error()) ? evaluationCancelled()
                                                  : fileError(map.name, cones.error().message);
            (conservative ? p.cone : p.relaxedCone) = std::make_shared<ConeMap>(std::move(*cones));
            step(std::string("baked the ") + (conservative ? "cone" : "relaxed cone") + " map of " +
                 map.name);
        }
        if (needs(&TechniqueInfo::needsPyramid)) {
            if (stopped())
                return evaluationCancelled();
            p.pyramid = std::make_shared<MaxMipPyramid>(MaxMipPyramid::build(field, m_config.wrap));
            step("built the max-mip pyramid of " + map.name);
        }
        m_prepared.push_back(std::move(p));
    }
    return success();
}

Status BenchRun::tracePolar(double polar, BenchReport& report) {
    const std::string angle = "polar " + formatAngle(polar);
    TraceScene scene;
    scene.rays = m_config.rays;
    scene.polarDeg = polar;
    scene.azimuthDeg = m_config.azimuthDeg;

    // The exact hits of every map and scale at this angle: the reference of every setting.
    struct Condition {
        const PreparedMap* map;
        float scale;
        std::vector<TraceResult> reference;
    };
    std::vector<Condition> conditions;
    for (const PreparedMap& map : m_prepared) {
        for (float scale : m_config.scales) {
            Result<Tracer> exact = Tracer::create(map.maps(m_config.wrap), Technique::Exact,
                                                  info(Technique::Exact).defaults, scale);
            if (!exact)
                return fileError(map.source->name, exact.error().message);
            Condition c{&map, scale, {}};
            if (!traceBatch(*exact, scene, RayTiming::Parallel, c.reference, m_control.cancel))
                return evaluationCancelled();
            conditions.push_back(std::move(c));
            step("exact reference of " + map.source->name + ", " + angle);
        }
    }

    for (const BenchSetting& setting : m_config.settings) {
        HitErrorAccumulator pooledErrors;
        double pooledNs = 0.0, pooledGpuMs = 0.0;
        int gpuCount = 0;
        bool timed = m_config.timingRepeats > 0;
        std::string pooledRenderer = m_config.gpuTimer ? std::string() : m_config.gpuUnavailable;
        for (const Condition& c : conditions) {
            const HeightField& field = *c.map->source->field;
            Result<Tracer> tracer = Tracer::create(c.map->maps(m_config.wrap), setting.technique,
                                                   setting.params, c.scale);
            if (!tracer)
                return fileError(c.map->source->name, tracer.error().message);
            BenchRow row;
            row.map = c.map->source->name;
            row.width = field.width;
            row.height = field.height;
            row.scale = c.scale;
            row.polarDeg = polar;
            row.setting = setting;

            std::vector<TraceResult> hits;
            if (timed) {
                double best = 0.0;
                for (int pass = 0; pass < m_config.timingRepeats; ++pass) {
                    std::vector<TraceResult> passHits;
                    const std::optional<double> ns = traceBatch(
                        *tracer, scene, RayTiming::OneThread, passHits, m_control.cancel);
                    if (!ns)
                        return evaluationCancelled();
                    best = pass == 0 ? *ns : std::min(best, *ns);
                    if (pass == 0)
                        hits = std::move(passHits);
                }
                row.cpuNsPerRay = best / static_cast<double>(hits.size());
                pooledNs += best;
            } else if (!traceBatch(*tracer, scene, RayTiming::Parallel, hits, m_control.cancel)) {
                return evaluationCancelled();
            }
            row.stats = measureHits(hits, c.reference, field.width, field.height);
            pooledErrors.add(hits, c.reference, field.width, field.height);

            row.gpuRenderer = m_config.gpuUnavailable;
            if (m_config.gpuTimer) {
                GpuFrameRequest request;
                request.maps = c.map->maps(m_config.wrap);
                request.setting = &setting;
                request.scale = c.scale;
                request.polarDeg = polar;
                request.azimuthDeg = m_config.azimuthDeg;
                Result<GpuFrameTiming> gpu = m_config.gpuTimer(request);
                if (gpu) {
                    row.gpuMsPerFrame = gpu->msPerFrame;
                    row.gpuRenderer = gpu->renderer;
                    pooledGpuMs += gpu->msPerFrame;
                    pooledRenderer = gpu->renderer;
                    report.gpuNote = gpu->renderer;
                    ++gpuCount;
                } else {
                    row.gpuRenderer = gpu.error().message;
                    pooledRenderer = gpu.error().message;
                    if (report.gpuNote.empty())
                        report.gpuNote = gpu.error().message;
                }
            }
            report.rows.push_back(std::move(row));
            step(std::string(info(setting.technique).name) +
                 (setting.label.empty() ? "" : " " + setting.label) + ", " + c.map->source->name +
                 ", " + angle);
        }

        BenchRow pooled;
        pooled.map = "all";
        pooled.polarDeg = polar;
        pooled.setting = setting;
        pooled.stats = pooledErrors.stats();
        pooled.pooled = true;
        if (timed && pooled.stats.rays > 0)
            pooled.cpuNsPerRay = pooledNs / static_cast<double>(pooled.stats.rays);
        if (gpuCount > 0 && gpuCount == static_cast<int>(conditions.size()))
            pooled.gpuMsPerFrame = pooledGpuMs / gpuCount;
        pooled.gpuRenderer = pooledRenderer;
        report.pooled.push_back(std::move(pooled));
    }
    return success();
}

Result<BenchReport> BenchRun::run() {
    if (Status s = validate(m_config); !s)
        return s.error();
    const int conditions = static_cast<int>(m_config.maps.size() * m_config.scales.size());
    const int polars = static_cast<int>(m_config.polarDeg.size());
    const int bakes =
        static_cast<int>(m_config.maps.size()) *
        (needs(&TechniqueInfo::needsConeMap) + needs(&TechniqueInfo::needsRelaxedConeMap) +
         needs(&TechniqueInfo::needsPyramid));
    m_progressState.total =
        bakes + polars * conditions * (1 + static_cast<int>(m_config.settings.size()));

    BenchReport report;
    report.wrap = m_config.wrap;
    report.azimuthDeg = m_config.azimuthDeg;
    report.rays = m_config.rays;
    report.polarDeg = m_config.polarDeg;
    report.gpuNote = m_config.gpuTimer ? std::string() : m_config.gpuUnavailable;

    if (Status s = prepareMaps(); !s)
        return s.error();
    for (double polar : m_config.polarDeg) {
        if (Status s = tracePolar(polar, report); !s)
            return s.error();
    }
    return report;
}

} // namespace

Status validate(const BenchConfig& c) {
    if (c.maps.empty())
        return Error{"the benchmark needs at least one height map"};
    for (const BenchMap& map : c.maps) {
        if (!map.field || map.field->empty())
            return fileError(map.name, "the height map is empty");
    }
    if (c.settings.empty())
        return Error{"the benchmark needs at least one technique setting"};
    for (const BenchSetting& s : c.settings) {
        if (!info(s.technique).parallax)
            return Error{std::string(info(s.technique).name) +
                         " traces no rays: nothing to measure"};
        if (Status v = validate(s.params); !v)
            return v.error().prefixed(std::string(info(s.technique).name) + ": ");
    }
    if (c.polarDeg.empty())
        return Error{"the benchmark needs at least one polar angle"};
    for (std::size_t k = 0; k < c.polarDeg.size(); ++k) {
        const double polar = c.polarDeg[k];
        if (!(polar >= 0.0 && polar < 90.0))
            return Error{"polar angle " + formatAngle(polar) + " is outside [0, 90) degrees"};
        if (std::count(c.polarDeg.begin(), c.polarDeg.begin() + k, polar) > 0)
            return Error{"polar angle " + formatAngle(polar) + " is listed twice"};
    }
    if (!std::isfinite(c.azimuthDeg))
        return Error{"the azimuth must be a finite angle"};
    if (c.scales.empty())
        return Error{"the benchmark needs at least one height scale"};
    for (std::size_t k = 0; k < c.scales.size(); ++k) {
        const float s = c.scales[k];
        if (!(std::isfinite(s) && s >= 0.0f))
            return Error{"height scale " + formatAngle(s) + " is not a finite number >= 0"};
        if (std::count(c.scales.begin(), c.scales.begin() + k, s) > 0)
            return Error{"height scale " + formatAngle(s) + " is listed twice"};
    }
    if (c.rays < 1 || c.rays > 4096)
        return Error{"rays must be 1 to 4096 per side, not " + std::to_string(c.rays)};
    if (c.timingRepeats < 0 || c.timingRepeats > 100)
        return Error{"timing repeats must be 0 to 100, not " + std::to_string(c.timingRepeats)};
    return success();
}

Result<BenchReport> runBench(const BenchConfig& config, const EvalControl& control) {
    return BenchRun(config, control).run();
}

std::vector<std::string> exactnessFailures(const BenchReport& report) {
    std::vector<std::string> failures;
    auto check = [&](const BenchRow& row) {
        if (!isDocumentedExact(row.setting.technique) || row.stats.maxError <= kExactTexels)
            return;
        char text[96];
        std::snprintf(text, sizeof text, " at %g deg: a ray %.3g texels from exact (> %g)",
                      row.polarDeg, row.stats.maxError, kExactTexels);
        std::string where = row.pooled ? "every map and scale" : row.map;
        if (row.scale)
            where += ", scale " + formatAngle(*row.scale);
        failures.push_back(std::string(info(row.setting.technique).name) + " (" +
                           row.setting.label + "), " + where + text);
    };
    for (const BenchRow& row : report.rows)
        check(row);
    for (const BenchRow& row : report.pooled)
        check(row);
    return failures;
}

} // namespace px

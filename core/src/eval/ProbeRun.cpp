#include "ProbeRun.h"

#include "bake/ConeCacheFile.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/io/Fnv1a.h"

#include <algorithm>
#include <cstdio>
#include <mutex>

namespace px {
namespace {

// The process-wide cache. Entries are small (figures) except the derived maps and the exact
// hits, of which only the latest few maps are kept.
struct ProbeCache {
    std::mutex mutex;
    std::map<std::string, AngleMeasure> angles;
    // Angles given up mid-trace as dearer than a limit: a lower bound of their mean fetches.
    std::map<std::string, double> fetchesAtLeast;
    std::map<std::string, std::shared_ptr<const std::vector<TraceResult>>> references;
    std::map<std::string, std::shared_ptr<const ConeMap>> cones;
    std::map<std::string, std::shared_ptr<const MaxMipPyramid>> pyramids;

    void trim() {
        if (angles.size() > 200000)
            angles.clear();
        if (fetchesAtLeast.size() > 200000)
            fetchesAtLeast.clear();
        if (references.size() > 256)
            references.clear();
        if (cones.size() > 8)
            cones.clear();
        if (pyramids.size() > 4)
            pyramids.clear();
    }
};

ProbeCache& cache() {
    static ProbeCache instance;
    return instance;
}

// Over the texels' bytes: equal maps share their measures, whatever file they came from.
std::uint64_t contentHash(const HeightField& field) {
    return fnv1a(field.texels.data(), field.texels.size() * sizeof(float));
}

// What a measure of a cone technique depends on besides the height map: a cone map the caller
// supplied (by content: the editor passes its own bakes) or the one baked from the height map.
std::string coneKey(const char* name, const std::shared_ptr<const ConeMap>& supplied) {
    if (!supplied)
        return std::string("/") + name + ":baked";
    const ConeMap& c = *supplied;
    char key[80];
    std::snprintf(key, sizeof key, "/%s:%016llx/%dx%d", name,
                  static_cast<unsigned long long>(
                      fnv1a(c.sqrtRatio.data(), c.sqrtRatio.size() * sizeof(float))),
                  c.width, c.height);
    return key;
}

std::string number(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

} // namespace

void clearProbeCache() {
    ProbeCache& c = cache();
    std::lock_guard lock(c.mutex);
    c.angles.clear();
    c.fetchesAtLeast.clear();
    c.references.clear();
    c.cones.clear();
    c.pyramids.clear();
}

ProbeRun::ProbeRun(const RecommendConfig& config, const EvalControl& control)
    : m_config(config), m_control(control), m_polars(recommendationPolars(config.maxPolarDeg)) {
    const HeightField& field = *config.field;
    m_contentHash = contentHash(field);
    char key[64];
    std::snprintf(key, sizeof key, "%016llx/%dx%d/", static_cast<unsigned long long>(m_contentHash),
                  field.width, field.height);
    m_contentKey = std::string(key) + std::string(toString(config.wrap));
    m_mapKey = m_contentKey + "/s" + number(config.scale) + "/r" +
               std::to_string(config.raysPerSide) + "/c" + number(config.confidence) + "/a";
    for (double a : config.azimuthDeg)
        m_mapKey += number(a) + ",";
    m_measureKey = m_mapKey + coneKey("cone", config.cone) + coneKey("relaxed", config.relaxedCone);
    m_maps.height = config.field.get();
    m_maps.heightMax = field.maxHeight();
    m_maps.wrap = config.wrap;
    m_cone = config.cone;
    m_relaxedCone = config.relaxedCone;
}

Status ProbeRun::prepare(const std::vector<Technique>& techniques) {
    auto needs = [&](bool TechniqueInfo::*flag) {
        return std::any_of(techniques.begin(), techniques.end(),
                           [&](Technique t) { return info(t).*flag; });
    };
    const HeightField& field = *m_config.field;
    const std::string& key = m_contentKey;
    for (ConeKind kind : {ConeKind::Conservative, ConeKind::Relaxed}) {
        const bool conservative = kind == ConeKind::Conservative;
        std::shared_ptr<const ConeMap>& slot = conservative ? m_cone : m_relaxedCone;
        if (slot || !needs(conservative ? &TechniqueInfo::needsConeMap
                                        : &TechniqueInfo::needsRelaxedConeMap))
            continue;
        const std::string coneKey = key + (conservative ? "/cone" : "/relaxed");
        {
            std::lock_guard lock(cache().mutex);
            auto it = cache().cones.find(coneKey);
            if (it != cache().cones.end())
                slot = it->second;
        }
        if (slot)
            continue;
        const ConeCacheKey diskKey{m_contentHash, field.width, field.height, m_config.wrap, kind};
        std::optional<ConeMap> kept;
        if (!m_config.cacheDir.empty()) {
            Result<std::optional<ConeMap>> read = readCachedCone(m_config.cacheDir, diskKey);
            if (!read)
                return read.error();
            kept = std::move(*read);
        }
        if (kept) {
            slot = std::make_shared<const ConeMap>(std::move(*kept));
            ++m_mapsFromDisk;
        } else {
            // The bake is what a first run on a map waits for: its progress is recommend()'s.
            BakeControl bakeControl{{}, m_control.cancel};
            if (m_control.progress) {
                const char* stage = conservative ? "baking cone map" : "baking relaxed-cone map";
                bakeControl.progress = [this, stage](float done) {
                    m_control.progress({static_cast<int>(done * 1000.0f), 1000, stage});
                };
            }
            Result<ConeMap> baked =
                m_config.coneBaker ? m_config.coneBaker(field, m_config.wrap, kind, bakeControl)
                                   : bakeConeMap(field, m_config.wrap, kind, bakeControl);
            if (!baked)
                return isCancelled(baked.error())
                           ? Status(evaluationCancelled())
                           : Status(fileError(m_config.name, baked.error().message));
            slot = std::make_shared<const ConeMap>(std::move(*baked));
            ++m_mapsBaked;
            if (!m_config.cacheDir.empty()) {
                if (Status s = writeCachedCone(m_config.cacheDir, diskKey, *slot,
                                               m_config.cacheLimitBytes);
                    !s)
                    m_cacheProblem = s.error().message;
            }
        }
        std::lock_guard lock(cache().mutex);
        cache().trim();
        cache().cones[coneKey] = slot;
    }
    if (needs(&TechniqueInfo::needsPyramid) && !m_pyramid) {
        const std::string pyramidKey = key + "/pyramid";
        std::lock_guard lock(cache().mutex);
        auto it = cache().pyramids.find(pyramidKey);
        if (it != cache().pyramids.end()) {
            m_pyramid = it->second;
        } else {
            m_pyramid =
                std::make_shared<const MaxMipPyramid>(MaxMipPyramid::build(field, m_config.wrap));
            cache().trim();
            cache().pyramids[pyramidKey] = m_pyramid;
        }
    }
    m_maps.cone = m_cone.get();
    m_maps.relaxedCone = m_relaxedCone.get();
    m_maps.pyramid = m_pyramid.get();
    return success();
}

std::int64_t ProbeRun::raysPerAngle() const {
    return static_cast<std::int64_t>(m_config.raysPerSide) * m_config.raysPerSide *
           static_cast<std::int64_t>(m_config.azimuthDeg.size());
}

Result<const RaySample*> ProbeRun::rays(std::size_t polarIndex, RayModel model) {
    auto [it, inserted] = m_rays.try_emplace({polarIndex, model});
    if (inserted)
        it->second = sampleRays(m_config.raysPerSide, m_polars[polarIndex], m_config.azimuthDeg,
                                m_config.scale, model);
    return &it->second;
}

Result<const std::vector<TraceResult>*> ProbeRun::reference(std::size_t polarIndex,
                                                            RayModel model) {
    auto& slot = m_references[{polarIndex, model}];
    if (slot)
        return slot.get();
    const std::string key = m_mapKey + "/p" + number(m_polars[polarIndex]) +
                            (model == RayModel::Relief ? "/relief" : "/view");
    {
        std::lock_guard lock(cache().mutex);
        auto it = cache().references.find(key);
        if (it != cache().references.end()) {
            slot = it->second;
            return slot.get();
        }
    }
    TraceMaps heightOnly;
    heightOnly.height = m_maps.height;
    heightOnly.wrap = m_maps.wrap;
    Result<Tracer> exact = Tracer::create(heightOnly, Technique::Exact,
                                          info(Technique::Exact).defaults, m_config.scale);
    if (!exact)
        return fileError(m_config.name, exact.error().message);
    Result<const RaySample*> sample = rays(polarIndex, model);
    std::optional<std::vector<TraceResult>> hits =
        traceSample(**sample, tracerRange(*exact), m_control.cancel);
    if (!hits)
        return evaluationCancelled();
    slot = std::make_shared<const std::vector<TraceResult>>(std::move(*hits));
    std::lock_guard lock(cache().mutex);
    cache().trim();
    cache().references[key] = slot;
    return slot.get();
}

Result<ProbeRun::Measured> ProbeRun::measure(const Probe& probe, bool timeCpu, double costLimit,
                                             std::size_t maxAngles) {
    Measured out;
    std::optional<RangeTrace> trace;
    const HeightField& field = *m_config.field;
    for (std::size_t p = 0; p < std::min(m_polars.size(), maxAngles); ++p) {
        if (m_control.cancelled())
            return evaluationCancelled();
        const std::string key =
            m_measureKey + "/p" + number(m_polars[p]) + "/" + probe.key + (timeCpu ? "/cpu" : "");
        std::optional<AngleMeasure> m;
        double knownAtLeast = 0.0;
        {
            std::lock_guard lock(cache().mutex);
            auto it = cache().angles.find(key);
            if (it != cache().angles.end())
                m = it->second;
            auto partial = cache().fetchesAtLeast.find(key);
            if (partial != cache().fetchesAtLeast.end())
                knownAtLeast = partial->second;
        }
        if (!m && !timeCpu && knownAtLeast > costLimit) {
            ++m_cached; // given up before, over a limit no higher than this one
            out.dearer = true;
            return out;
        }
        if (m) {
            ++m_cached;
        } else {
            if (!trace) {
                Result<RangeTrace> made = probe.make();
                if (!made)
                    return fileError(m_config.name, made.error().message);
                trace = std::move(*made);
            }
            Result<const RaySample*> sample = rays(p, probe.model);
            Result<const std::vector<TraceResult>*> ref = reference(p, probe.model);
            if (!ref)
                return ref.error();
            // Fetches bound the trace itself; ns per ray are known only once it is timed.
            const double limit = timeCpu ? std::numeric_limits<double>::infinity() : costLimit;
            double atLeast = 0.0;
            std::optional<std::vector<TraceResult>> hits =
                traceSampleWithin(**sample, *trace, m_control.cancel, limit, atLeast);
            if (!hits && atLeast > limit) {
                ++m_measured;
                std::lock_guard lock(cache().mutex);
                cache().trim();
                double& known = cache().fetchesAtLeast[key];
                known = std::max(known, atLeast);
                out.dearer = true;
                return out;
            }
            if (!hits)
                return evaluationCancelled();
            m = measureAngle(**sample, *hits, **ref, field.width, field.height,
                             m_config.confidence);
            if (timeCpu)
                m->cpuNsPerRay = timeSample(**sample, *trace);
            ++m_measured;
            std::lock_guard lock(cache().mutex);
            cache().trim();
            cache().angles[key] = *m;
        }
        m->meets = meetsBudget(*m, m_config.budget);
        out.angles.push_back(*m);
        if (!m->meets)
            break;
        if ((timeCpu ? m->cpuNsPerRay.value_or(0.0) : m->meanFetches) > costLimit) {
            out.dearer = true;
            break;
        }
    }
    return out;
}

} // namespace px

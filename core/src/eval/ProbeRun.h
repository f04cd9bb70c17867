#pragma once
// Measures candidate settings of a recommendation angle by angle, steepest first, stopping at the
// first angle a setting fails; each angle's rays and exact hits are drawn once and shared by every
// candidate. Every measure goes through a process-wide cache keyed by the map's content, size and
// wrap, the scale, the sampling, the cone maps supplied and the candidate, so a second question
// about the same material (another budget, the editor asking again) traces nothing it has traced
// before.

#include "RayProbe.h"
#include "parallax/bake/MaxMipPyramid.h"

#include <limits>
#include <map>
#include <memory>
#include <string>

namespace px {

// A candidate: a stable key (technique and parameters, or an engine march and its layers), the
// rays it takes, and how to make its tracer (called at most once, only on a cache miss).
struct Probe {
    std::string key;
    RayModel model = RayModel::Relief;
    std::function<Result<RangeTrace>()> make;
};

class ProbeRun {
public:
    ProbeRun(const RecommendConfig& config, const EvalControl& control);

    // Bakes or fetches from the cache the derived maps the listed techniques read.
    Status prepare(const std::vector<Technique>& techniques);
    const TraceMaps& maps() const { return m_maps; }
    const std::vector<double>& polars() const { return m_polars; }

    // The angles of one candidate, steepest first, up to and including the first that fails the
    // budget (all of them if none does). timeCpu: also the one-thread ns per ray.
    // costLimit: stop, `dearer` set, at the first angle whose cost (mean fetches, or with timeCpu
    // ns per ray) is over it, mid-trace where the fetches made so far already are; an angle given
    // up mid-trace is left out of `angles` and of the cache.
    struct Measured {
        std::vector<AngleMeasure> angles;
        bool dearer = false;
    };
    // maxAngles: the steepest ones only (the rest are measured by a later call, from the cache).
    Result<Measured> measure(const Probe& probe, bool timeCpu,
                             double costLimit = std::numeric_limits<double>::infinity(),
                             std::size_t maxAngles = std::numeric_limits<std::size_t>::max());

    int cachedAngles() const { return m_cached; }
    int measuredAngles() const { return m_measured; }
    int mapsBaked() const { return m_mapsBaked; }
    int mapsFromDisk() const { return m_mapsFromDisk; }
    const std::string& cacheProblem() const { return m_cacheProblem; }
    std::int64_t raysPerAngle() const;

private:
    Result<const RaySample*> rays(std::size_t polarIndex, RayModel model);
    Result<const std::vector<TraceResult>*> reference(std::size_t polarIndex, RayModel model);

    const RecommendConfig& m_config;
    const EvalControl& m_control;
    std::uint64_t m_contentHash = 0;
    std::string m_contentKey; // content hash, size and wrap: what the derived maps depend on
    std::string m_mapKey;     // and the scale and sampling: what the exact hits depend on
    std::string m_measureKey; // and the cone maps supplied: what the measures depend on
    std::vector<double> m_polars;
    TraceMaps m_maps;
    std::shared_ptr<const ConeMap> m_cone, m_relaxedCone;
    std::shared_ptr<const MaxMipPyramid> m_pyramid;
    std::map<std::pair<std::size_t, RayModel>, RaySample> m_rays;
    std::map<std::pair<std::size_t, RayModel>, std::shared_ptr<const std::vector<TraceResult>>>
        m_references;
    int m_cached = 0;
    int m_measured = 0;
    int m_mapsBaked = 0, m_mapsFromDisk = 0; // cone maps, this run
    std::string m_cacheProblem;              // why a bake could not be kept in cacheDir
};

void clearProbeCache();

} // namespace px

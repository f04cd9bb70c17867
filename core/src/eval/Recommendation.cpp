#include "parallax/eval/Recommendation.h"

#include "ProbeRun.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace px {
namespace {

// About 12% apart up to 256 (4, 5, 6, ... 224, 256), then 320, 400, 512.
constexpr int kRungs[] = {4,   5,   6,   7,   8,   9,   10,  11,  12,  14,  16,  18, 20,
                          22,  25,  28,  32,  36,  40,  45,  50,  56,  64,  72,  80, 90,
                          100, 112, 128, 144, 160, 180, 200, 224, 256, 320, 400, 512};

BenchSetting makeSetting(Technique t, const TraceParams& p) {
    const TraceParams& d = info(t).defaults;
    const bool isDefault = p.minLayers == d.minLayers && p.maxLayers == d.maxLayers &&
                           p.binarySteps == d.binarySteps && p.secantSteps == d.secantSteps &&
                           p.maxSteps == d.maxSteps;
    return BenchSetting{t, p, settingLabel(t, p), isDefault};
}

std::string probeKey(const BenchSetting& s) {
    const TraceParams& p = s.params;
    return std::string(info(s.technique).name) + ":" + std::to_string(p.minLayers) + "-" +
           std::to_string(p.maxLayers) + "/" + std::to_string(p.binarySteps) + "/" +
           std::to_string(p.secantSteps) + "/" + std::to_string(p.maxSteps);
}

Probe techniqueProbe(const BenchSetting& s, const TraceMaps& maps, float scale) {
    Probe probe;
    probe.key = probeKey(s);
    probe.model = RayModel::Relief;
    probe.make = [s, maps, scale]() -> Result<RangeTrace> {
        Result<Tracer> tracer = Tracer::create(maps, s.technique, s.params, scale);
        if (!tracer)
            return tracer.error();
        auto owned = std::make_shared<Tracer>(std::move(*tracer));
        RangeTrace inner = tracerRange(*owned);
        return RangeTrace(
            [owned, inner](const RaySample& rays, std::size_t begin, std::size_t end,
                           std::span<TraceResult> hits) { inner(rays, begin, end, hits); });
    };
    return probe;
}

// One angle's cost in CPU time or fetches (GPU time is the whole frame's: costOf()).
double angleCost(const AngleMeasure& a, CostMeasure cost) {
    return cost == CostMeasure::CpuTime ? a.cpuNsPerRay.value_or(0.0) : a.meanFetches;
}

double costOf(const MeasuredSetting& m, CostMeasure cost) {
    double c = 0.0;
    for (const AngleMeasure& a : m.angles)
        c = std::max(c, angleCost(a, cost));
    if (cost == CostMeasure::GpuTime)
        return m.gpuMsPerFrame.value_or(std::numeric_limits<double>::infinity());
    return c;
}

} // namespace

std::vector<double> recommendationPolars(double maxPolarDeg) {
    std::vector<double> polars;
    for (double below : {0.0, 5.0, 10.0, 20.0, 40.0, 60.0}) {
        if (maxPolarDeg - below >= 0.0)
            polars.push_back(maxPolarDeg - below);
    }
    return polars;
}

std::vector<std::vector<BenchSetting>> recommendationLadders(const std::vector<Technique>& only) {
    std::vector<std::vector<BenchSetting>> ladders;
    auto wanted = [&](Technique t) {
        return only.empty() || std::find(only.begin(), only.end(), t) != only.end();
    };
    auto ladder = [&](Technique t, int maxRung, auto&& setParams) {
        if (!wanted(t))
            return;
        std::vector<BenchSetting> rungs;
        for (int n : kRungs) {
            if (n > maxRung)
                break;
            TraceParams p = info(t).defaults;
            setParams(p, n);
            rungs.push_back(makeSetting(t, p));
        }
        ladders.push_back(std::move(rungs));
    };
    if (wanted(Technique::Offset))
        ladders.push_back({makeSetting(Technique::Offset, info(Technique::Offset).defaults)});
    // Layer marches: n layers at grazing angles, n/4 looking down (the tutorials' 8-32 shape).
    auto layers = [](TraceParams& p, int n) {
        p.maxLayers = n;
        p.minLayers = std::max(1, (n + 2) / 4);
    };
    for (Technique t : {Technique::Steep, Technique::Pom, Technique::Secant})
        ladder(t, 256, layers);
    for (int binary : {3, 6})
        ladder(Technique::Relief, 256, [&](TraceParams& p, int n) {
            layers(p, n);
            p.binarySteps = binary;
        });
    ladder(Technique::Cone, 512, [](TraceParams& p, int n) { p.maxSteps = n; });
    // Its last step is solved exactly (no binary steps to choose).
    ladder(Technique::RelaxedCone, 256, [](TraceParams& p, int n) { p.maxSteps = n; });
    ladder(Technique::Pyramid, 512, [](TraceParams& p, int n) { p.maxSteps = n; });
    if (wanted(Technique::Pyramid)) // uncapped: exact
        ladders.back().push_back(
            makeSetting(Technique::Pyramid, info(Technique::Pyramid).defaults));
    if (wanted(Technique::Exact))
        ladders.push_back({makeSetting(Technique::Exact, info(Technique::Exact).defaults)});
    return ladders;
}

bool costFallsAlongLadder(Technique t) {
    return t == Technique::Cone || t == Technique::RelaxedCone || t == Technique::Pyramid;
}

namespace {

// Reorders order[from..] so that the capped ladders (whose top rung is their cheapest) come
// cheapest top first, judged at the steepest angle alone, where rays cost most: the first then
// sets a low cost that the others' tops are given up against, often at that one angle. Tops
// that fail there, or cost more than `limit`, go last. The order changes no answer: candidates
// are compared in ladder order at the end. On spike-flat 2048² it halved the warm run. Only
// worth it where dearer settings are given up (CPU time or fetches).
Status orderCappedLadders(ProbeRun& run, const RecommendConfig& config,
                          const std::vector<std::vector<BenchSetting>>& ladders, double limit,
                          std::size_t from, std::vector<std::size_t>& order) {
    const bool timeCpu = config.cost == CostMeasure::CpuTime;
    std::vector<std::size_t> slots;
    std::vector<std::pair<double, std::size_t>> steepest; // cost there, ladder
    for (std::size_t k = from; k < order.size(); ++k) {
        const std::vector<BenchSetting>& ladder = ladders[order[k]];
        if (!costFallsAlongLadder(ladder.front().technique))
            continue;
        Result<ProbeRun::Measured> m =
            run.measure(techniqueProbe(ladder.back(), run.maps(), config.scale), timeCpu, limit, 1);
        if (!m)
            return m.error();
        const bool meets = !m->dearer && !m->angles.empty() && m->angles.front().meets;
        const double cost = meets ? angleCost(m->angles.front(), config.cost)
                                  : std::numeric_limits<double>::infinity();
        slots.push_back(k);
        steepest.emplace_back(cost, order[k]);
    }
    std::stable_sort(steepest.begin(), steepest.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k < slots.size(); ++k)
        order[slots[k]] = steepest[k].second;
    return success();
}

} // namespace

Status validate(const RecommendConfig& c) {
    if (!c.field || c.field->empty())
        return fileError(c.name, "the height map is empty");
    if (!(std::isfinite(c.scale) && c.scale >= 0.0f))
        return Error{"the height scale must be a finite number >= 0"};
    if (!(c.maxPolarDeg >= 0.0 && c.maxPolarDeg <= 89.0))
        return Error{"the maximum polar angle must be 0 to 89 degrees"};
    if (c.azimuthDeg.empty())
        return Error{"the view range needs at least one azimuth"};
    if (!std::all_of(c.azimuthDeg.begin(), c.azimuthDeg.end(),
                     [](double a) { return std::isfinite(a); }))
        return Error{"every azimuth must be a finite angle"};
    if (!(std::isfinite(c.budget.texels) && c.budget.texels >= 0.0))
        return Error{"the error budget must be a finite number of texels >= 0"};
    if (c.raysPerSide < 4 || c.raysPerSide > 256)
        return Error{"rays per side must be 4 to 256, not " + std::to_string(c.raysPerSide)};
    if (!(c.confidence > 0.5 && c.confidence < 1.0))
        return Error{"the confidence must be between 0.5 and 1"};
    for (Technique t : c.techniques) {
        if (!info(t).parallax)
            return Error{"'" + std::string(info(t).name) + "' traces no rays: it cannot be chosen"};
    }
    if (c.cost == CostMeasure::GpuTime && !c.gpuTimer)
        return Error{"no GPU timing" +
                     (c.gpuUnavailable.empty() ? std::string() : ": " + c.gpuUnavailable) +
                     " (use the fetches or cpu cost)"};
    return success();
}

void clearRecommendationCache() {
    clearProbeCache();
}

Result<Recommendation> recommend(const RecommendConfig& config, const EvalControl& control) {
    if (Status s = validate(config); !s)
        return s.error();
    std::vector<std::vector<BenchSetting>> ladders = recommendationLadders(config.techniques);
    std::vector<Technique> techniques;
    techniques.reserve(ladders.size());
    for (const auto& l : ladders)
        techniques.push_back(l.front().technique);

    ProbeRun run(config, control);
    if (Status s = run.prepare(techniques); !s)
        return s.error();
    const bool timeCpu = config.cost == CostMeasure::CpuTime;

    Recommendation r;
    r.polarDeg = run.polars();
    r.raysPerAngle = run.raysPerAngle();
    // Per ladder that has one (its index, then the setting's), its cheapest rung that meets.
    std::vector<std::pair<std::size_t, std::size_t>> candidates;
    // The cost of the cheapest meeting setting so far: a setting found dearer at any angle cannot
    // be chosen, so its measure stops there (GPU time is only known at the end).
    double bestCost = std::numeric_limits<double>::infinity();
    const bool giveUp = config.cost != CostMeasure::GpuTime && config.giveUpDearer;
    auto measureRung = [&](const BenchSetting& s, double limit) -> Result<std::size_t> {
        if (!giveUp)
            limit = std::numeric_limits<double>::infinity();
        Result<ProbeRun::Measured> measured =
            run.measure(techniqueProbe(s, run.maps(), config.scale), timeCpu, limit);
        if (!measured)
            return measured.error();
        MeasuredSetting m;
        m.setting = s;
        m.angles = std::move(measured->angles);
        m.dearer = measured->dearer;
        m.meets = !m.dearer && m.angles.size() == run.polars().size() && m.angles.back().meets;
        r.measured.push_back(std::move(m));
        return r.measured.size() - 1;
    };
    // The ladders in the order they are searched: as given, up to the first capped one, from
    // where orderCappedLadders() reorders them once the ladders before it have set bestCost.
    std::vector<std::size_t> order(ladders.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto firstCapped = static_cast<std::size_t>(
        std::find_if(ladders.begin(), ladders.end(),
                     [](const auto& l) { return costFallsAlongLadder(l.front().technique); }) -
        ladders.begin());
    for (std::size_t at = 0; at < order.size(); ++at) {
        if (giveUp && at == firstCapped) {
            if (Status s = orderCappedLadders(run, config, ladders, bestCost, at, order); !s)
                return s.error();
        }
        const std::size_t ladderIndex = order[at];
        const std::vector<BenchSetting>& ladder = ladders[ladderIndex];
        // Quality rises along a ladder (if its top rung fails, none will), so the rungs that meet
        // are those from some rung up. Found by bisection, the top first.
        Result<std::size_t> top = measureRung(ladder.back(), bestCost);
        if (!top)
            return top.error();
        std::optional<std::size_t> best;
        if (costFallsAlongLadder(ladder.back().technique)) {
            // The top rung is the cheapest: the answer is the lowest rung that meets at its cost
            // (a cap may bind on some rays and cost nothing more, where the walk pays a fetch a
            // cell as the steps did). Rungs dearer than the top are given up at once.
            if (!r.measured[*top].meets)
                continue; // failing, or dearer than the best so far, and the rest are dearer
            best = *top;
            // GPU time is taken at the end, for the candidates: along a ladder, fetches stand in.
            const CostMeasure along =
                config.cost == CostMeasure::GpuTime ? CostMeasure::Fetches : config.cost;
            const double topCost = costOf(r.measured[*top], along);
            std::size_t lo = 0, hi = ladder.size() - 1;
            while (lo < hi) {
                const std::size_t mid = lo + (hi - lo) / 2;
                Result<std::size_t> at = measureRung(ladder[mid], topCost);
                if (!at)
                    return at.error();
                const MeasuredSetting& m = r.measured[*at];
                if (m.meets && costOf(m, along) <= topCost) {
                    hi = mid;
                    best = *at;
                } else {
                    lo = mid + 1;
                }
            }
        } else {
            // Cost rises along the ladder: the first rung that meets is the cheapest. A rung
            // found dearer than the best so far is taken as meeting for the bisection: if it
            // does not, the rung that does is dearer still, so the ladder has nothing to offer.
            if (!r.measured[*top].meets && !r.measured[*top].dearer)
                continue;
            if (r.measured[*top].meets)
                best = *top;
            std::size_t lo = 0, hi = ladder.size() - 1;
            while (lo < hi) {
                const std::size_t mid = lo + (hi - lo) / 2;
                Result<std::size_t> at = measureRung(ladder[mid], bestCost);
                if (!at)
                    return at.error();
                const MeasuredSetting& m = r.measured[*at];
                if (m.meets || m.dearer) {
                    hi = mid;
                    best = m.meets ? std::optional(*at) : std::nullopt;
                } else {
                    lo = mid + 1;
                }
            }
        }
        if (!best)
            continue;
        candidates.emplace_back(ladderIndex, *best);
        if (config.cost != CostMeasure::GpuTime)
            bestCost = std::min(bestCost, costOf(r.measured[*best], config.cost));
    }
    std::sort(candidates.begin(), candidates.end());

    for (auto [ladderIndex, k] : candidates) {
        MeasuredSetting& m = r.measured[k];
        if (config.cost == CostMeasure::GpuTime) {
            GpuFrameRequest request;
            request.maps = run.maps();
            request.setting = &m.setting;
            request.scale = config.scale;
            request.polarDeg = run.polars().front();
            request.azimuthDeg = config.azimuthDeg.front();
            Result<GpuFrameTiming> gpu = config.gpuTimer(request);
            if (!gpu)
                return Error{"GPU timing failed: " + gpu.error().message};
            m.gpuMsPerFrame = gpu->msPerFrame;
        }
        m.cost = costOf(m, config.cost);
    }
    // Cheapest; ties go to the lower error at the steepest angle, then to the ladder order.
    for (auto [ladderIndex, k] : candidates) {
        const MeasuredSetting& m = r.measured[k];
        if (!r.found || m.cost < r.chosen.cost ||
            (m.cost == r.chosen.cost && m.angles.front().p99 < r.chosen.angles.front().p99)) {
            r.chosen = m;
            r.found = true;
        }
    }
    // The Pareto front at the steepest angle, over every setting measured.
    // Settings given up at it (dearer) have no figures there and are left out.
    for (MeasuredSetting& m : r.measured) {
        if (m.angles.empty())
            continue;
        const AngleMeasure& a = m.angles.front();
        m.onFront =
            std::none_of(r.measured.begin(), r.measured.end(), [&](const MeasuredSetting& o) {
                if (o.angles.empty())
                    return false;
                const AngleMeasure& b = o.angles.front();
                return (b.meanFetches <= a.meanFetches && b.p99 <= a.p99) &&
                       (b.meanFetches < a.meanFetches || b.p99 < a.p99);
            });
        if (r.found && m.setting.technique == r.chosen.setting.technique &&
            probeKey(m.setting) == probeKey(r.chosen.setting))
            r.chosen.onFront = m.onFront;
    }
    if (r.found) {
        const TechniqueInfo& ti = info(r.chosen.setting.technique);
        r.maps.push_back("height");
        if (ti.needsConeMap)
            r.maps.push_back("cone");
        if (ti.needsRelaxedConeMap)
            r.maps.push_back("relaxed-cone");
        if (ti.needsPyramid)
            r.maps.push_back("pyramid");
    }
    r.confidence = confidenceStatement(config, r.raysPerAngle);
    r.cachedAngles = run.cachedAngles();
    r.measuredAngles = run.measuredAngles();
    r.mapsBaked = run.mapsBaked();
    r.mapsFromDisk = run.mapsFromDisk();
    r.cacheProblem = run.cacheProblem();
    return r;
}

} // namespace px

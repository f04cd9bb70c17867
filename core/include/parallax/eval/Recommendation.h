#pragma once
// The `auto` quality: the cheapest technique setting that keeps a material's hit error within a
// budget at every view angle up to a maximum. It measures each technique's quality ladder on a
// jittered subsample of rays (a few azimuths per polar angle), judges the budget on a
// distribution-free upper confidence bound rather than on the sample's own figure, and picks the
// least costly setting that meets it at every angle. Measurements are cached in memory by map
// content, scale and wrap (and the sampling), so asking again with another budget is cheap.
//
// Deterministic: the rays come from a fixed seed, so the same input gives the same answer (with
// the fetch cost; CPU and GPU times are measured and vary).

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/eval/Bench.h"
#include "parallax/eval/EvalControl.h"
#include "parallax/eval/QualitySweep.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace px {

enum class BudgetMetric {
    P99,            // 99th percentile of the hit error (the default)
    Max,            // every sampled ray
    NoWrongSurface, // p99 within budget and no ray further than kWrongSurfaceTexels
};
enum class CostMeasure { Fetches, CpuTime, GpuTime };

std::string_view budgetMetricName(BudgetMetric metric); // "p99", "max", "surface"
std::optional<BudgetMetric> parseBudgetMetric(std::string_view name);
std::string_view costMeasureName(CostMeasure cost); // "fetches", "cpu", "gpu"
std::optional<CostMeasure> parseCostMeasure(std::string_view name);

struct ErrorBudget {
    double texels = 0.5; // hit error in texels of the map (docs/conventions.md §5)
    BudgetMetric metric = BudgetMetric::P99;
};

// Texels of the map per screen pixel, for a budget given in pixels: a tile of `tiling` repeats
// across `surfaceWidth` world units, seen from `distance` with a vertical field of view `fovDeg`
// on a `screenHeight`-pixel screen. Fails on a non-positive or non-finite input.
struct ScreenDensity {
    int mapWidth = 0;
    double tiling = 1.0;
    double surfaceWidth = 1.0;
    double distance = 2.0;
    double fovDeg = 60.0;
    int screenHeight = 1080;
};
Result<double> texelsPerPixel(const ScreenDensity& density);

struct RecommendConfig {
    std::shared_ptr<const HeightField> field;
    std::string name; // the map's file, for messages
    WrapMode wrap = WrapMode::Repeat;
    float scale = 0.05f;
    double maxPolarDeg = 80.0;
    std::vector<double> azimuthDeg{15.0, 75.0, 135.0, 195.0, 255.0, 315.0};
    ErrorBudget budget;
    CostMeasure cost = CostMeasure::Fetches;
    int raysPerSide = 32;              // each azimuth: raysPerSide^2 stratified, jittered rays
    double confidence = 0.99;          // of the bounds the budget is judged on
    std::vector<Technique> techniques; // empty: every technique that traces rays
    // Stop measuring a setting once it is dearer than one already found to meet (the answer is
    // the same, since cost rises along a ladder); false measures every setting visited in full:
    // the check of that, and the benchmark's baseline.
    bool giveUpDearer = true;
    // Derived maps the caller already has (the editor, a material's files); others are baked once
    // and cached by content.
    std::shared_ptr<const ConeMap> cone;
    std::shared_ptr<const ConeMap> relaxedCone;
    // A folder where baked cone maps are kept between runs (empty: none), and how much of it
    // they may take; docs/recommend.md.
    std::string cacheDir;
    std::uint64_t cacheLimitBytes = std::uint64_t(2) << 30;
    GpuFrameTimer gpuTimer; // needed for CostMeasure::GpuTime
    std::string gpuUnavailable;
    // Bakes the cone maps not given, cached or kept (empty: bakeConeMap() on the CPU); the GPU's
    // bakers make the same maps (docs/bakers.md), so the cache and the answer do not depend on it.
    std::function<Result<ConeMap>(const HeightField&, WrapMode, ConeKind, const BakeControl&)>
        coneBaker;
};

// One polar angle of one setting, every azimuth's rays pooled.
struct AngleMeasure {
    double polarDeg = 0.0;
    std::int64_t rays = 0;
    double p99 = 0.0;      // the sample's nearest-rank p99, texels
    double p99Bound = 0.0; // upper confidence bound of the p99 (infinite if rays are too few)
    double maxError = 0.0;
    std::int64_t wrongSurface = 0; // rays further than kWrongSurfaceTexels (or invalid)
    double meanFetches = 0.0;
    std::optional<double> cpuNsPerRay; // one thread, with CostMeasure::CpuTime
    bool meets = false;
};

struct MeasuredSetting {
    BenchSetting setting;
    std::vector<AngleMeasure> angles; // steepest first; ends at the first angle that fails
    bool meets = false;               // at every angle
    // Given up at an angle whose cost was over that of a setting already found to meet (it cannot
    // be chosen): meets is then unknown and false, and that angle is missing if it was given up
    // mid-trace.
    bool dearer = false;
    double cost = 0.0; // max over the angles on the chosen measure (meeting ones)
    std::optional<double> gpuMsPerFrame;
    bool onFront = false; // Pareto front of error against fetches at the steepest angle
};

struct Recommendation {
    bool found = false;
    MeasuredSetting chosen; // found: the cheapest meeting setting
    std::vector<MeasuredSetting> measured;
    std::vector<double> polarDeg;  // the angles judged, steepest first
    std::vector<std::string> maps; // the maps the chosen setting reads: "height", "cone", ...
    std::string confidence;        // what the sample allows one to say about every ray
    std::int64_t raysPerAngle = 0;
    int cachedAngles = 0; // angle measures taken from the cache
    int measuredAngles = 0;
    int mapsBaked = 0;        // cone maps baked by this call
    int mapsFromDisk = 0;     // ... read from RecommendConfig::cacheDir instead
    std::string cacheProblem; // why baked maps could not be kept there (empty: they were)
};

// The polar angles a recommendation judges, steepest first: the maximum and 5, 10, 20, 40 and
// 60 degrees below it (those at or above 0).
std::vector<double> recommendationPolars(double maxPolarDeg);

// Each technique's quality ladders, lowest quality first, spaced about 12% apart so that a
// conservative choice is never more than one small step above the cheapest that would do.
std::vector<std::vector<BenchSetting>>
recommendationLadders(const std::vector<Technique>& only = {});

// Which way cost goes along a technique's ladder. The layer marches pay for every layer, so more
// layers cost more. The capped marches (cone, relaxed-cone, pyramid) walk every remaining cell
// exactly where their step cap runs out, so a lower cap costs more, not less: on a 2048² map of
// long flats with spikes, cone at 4 steps took 612 fetches a ray at 80 degrees, at 512 steps 164.
bool costFallsAlongLadder(Technique t);

// Errors: an empty map, a scale < 0, a polar angle outside [0, 89], no azimuth, a budget < 0,
// rays outside [4, 256], confidence outside (0.5, 1), gpu cost without a timer.
Status validate(const RecommendConfig& config);

// Fails with validate()'s errors, a bake or tracer error naming the map, or evaluationCancelled().
// Progress: only the cone bakes report (how long the search runs is not known ahead, and the
// bakes are what a first run on a map waits for): stage "baking cone map" or "baking relaxed-cone
// map", done of 1000 for that bake, called from the baker's threads, never concurrently.
Result<Recommendation> recommend(const RecommendConfig& config, const EvalControl& control = {});

// Empties the measurement cache (tests, and the editor when memory is short).
void clearRecommendationCache();

// What the sample lets one say about every ray: for p99, the rank of the bound and its confidence;
// for max and surface, the fraction of all rays that may exceed what none of the sample did.
std::string confidenceStatement(const RecommendConfig& config, std::int64_t raysPerAngle);

// "p99 ≤ 0.5 texel at every polar angle up to 80° ..." : the recommendation in one paragraph.
std::string describe(const Recommendation& r, const RecommendConfig& config);

} // namespace px

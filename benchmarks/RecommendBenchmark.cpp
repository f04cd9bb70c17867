// The `auto` recommendation on 2048² maps (noise, bricks, and spike-flat, the adversarial one:
// every ray at a grazing angle crosses long flats), target 2 s on 2 cores, four ways:
//   Warm: the cone and relaxed cone maps supplied (as by a material that has them, or the editor
//         that baked them), nothing measured before: every ray the recommendation needs is traced.
//   Cached: asked again with another budget: answered from the measurement cache.
//   Cold: nothing supplied: the cone bakes are part of the time (once per map content and wrap).
//   WarmInFull: as Warm, but every setting the search visits is measured in full instead of
//         being given up once dearer than one found to meet: the baseline of that saving.
// Reported: wall time, CPU seconds of all threads (divided by the cores, what the wall time would
// be with the machine to itself), and the ratio of the wall time to the 2 s target.
//
//   parallax-bench-recommend
//   parallax-bench-recommend --benchmark_filter=Warm

#include "ProcessCpu.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/eval/Recommendation.h"
#include "parallax/sample/ProceduralMaps.h"

#include <benchmark/benchmark.h>
#include <chrono>
#include <iterator>

using namespace px;

namespace {

constexpr double kTargetSeconds = 2.0;

struct Prepared {
    std::shared_ptr<const HeightField> field;
    std::shared_ptr<const ConeMap> cone, relaxed;
};

struct BenchMap {
    ProceduralMap map;
    const char* name;
};
constexpr BenchMap kMaps[] = {{ProceduralMap::Noise, "noise 2048"},
                              {ProceduralMap::Bricks, "bricks 2048"},
                              {ProceduralMap::SpikeFlat, "spike-flat 2048"}};

const Prepared& prepared(int kind) {
    static Prepared maps[std::size(kMaps)];
    Prepared& p = maps[kind];
    if (!p.field) {
        p.field = std::make_shared<HeightField>(makeProceduralMap(kMaps[kind].map, 2048, 2048, 1));
        p.cone = std::make_shared<ConeMap>(
            bakeConeMap(*p.field, WrapMode::Repeat, ConeKind::Conservative));
        p.relaxed =
            std::make_shared<ConeMap>(bakeConeMap(*p.field, WrapMode::Repeat, ConeKind::Relaxed));
    }
    return p;
}

enum class Mode { Warm, WarmInFull, Cached, Cold };

void run(benchmark::State& state, Mode mode) {
    const int kind = static_cast<int>(state.range(0));
    const Prepared& p = prepared(kind);
    RecommendConfig config;
    config.field = p.field;
    config.name = kMaps[kind].name;
    config.giveUpDearer = mode != Mode::WarmInFull;
    if (mode != Mode::Cold) {
        config.cone = p.cone;
        config.relaxedCone = p.relaxed;
    }
    double cpu = 0.0, wall = 0.0;
    std::string chosen;
    for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores): the loop idiom
        state.PauseTiming();
        clearRecommendationCache();
        if (mode == Mode::Cached) {
            config.budget.texels = 0.25;
            benchmark::DoNotOptimize(recommend(config));
            config.budget.texels = 0.5;
        }
        state.ResumeTiming();
        const double cpuBefore = bench::processCpuSeconds();
        const auto start = std::chrono::steady_clock::now();
        Result<Recommendation> r = recommend(config);
        wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        cpu += bench::processCpuSeconds() - cpuBefore;
        if (!r) {
            state.SkipWithError(r.error().message.c_str());
            return;
        }
        chosen =
            std::string(info(r->chosen.setting.technique).name) + " " + r->chosen.setting.label;
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["cpu_all_threads_s"] = cpu / n;
    state.counters["x_of_2s_target"] = wall / n / kTargetSeconds;
    state.SetLabel(config.name + ": " + chosen);
}

} // namespace

BENCHMARK_CAPTURE(run, Warm, Mode::Warm)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(run, WarmInFull, Mode::WarmInFull)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(run, Cached, Mode::Cached)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(run, Cold, Mode::Cold)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

BENCHMARK_MAIN();

// The bakers at the sizes of the targets (normal 4096², cone and relaxed cone 1024²), and the
// brute-force bakers at 256² with the fast ones at the same size, in the same run: the ratios
// printed at the end are the speed-ups. Peak memory is what a bake allocates on top of its input,
// as a multiple of the map's size in floats (target: under 4).
//
//   parallax-bench-bake                      # everything (the brute forces take a while)
//   parallax-bench-bake --benchmark_filter=Normal
//   parallax-bench-bake --benchmark_filter='Normal/2048|HeightFromNormalMap'  # vs the normal bake

#include "HeapCounter.h"
#include "ProcessCpu.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/ConeMapReference.h"
#include "parallax/bake/HeightFromNormals.h"
#include "parallax/bake/NormalMapBaker.h"
#include "parallax/bake/OcclusionBaker.h"
#include "parallax/sample/ProceduralMaps.h"

#include <benchmark/benchmark.h>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <thread>

using namespace px;

namespace {

// The maps: smooth value noise (wide cones, the search's worst case) and bricks (flat tops and
// steep mortar, an artist's typical map).
HeightField mapFor(int kind, int size) {
    return makeProceduralMap(kind == 0 ? ProceduralMap::Noise : ProceduralMap::Bricks, size, size,
                             1);
}

template <typename Bake> void run(benchmark::State& state, Bake bake) {
    const int size = static_cast<int>(state.range(0));
    const HeightField field = mapFor(static_cast<int>(state.range(1)), size);
    double peak = 0, cpu = 0;
    for (auto _ : state) {
        bench::resetHeapPeak();
        const std::size_t before = bench::heapInUse();
        const double cpuBefore = bench::processCpuSeconds();
        bake(field);
        cpu += bench::processCpuSeconds() - cpuBefore;
        peak = std::max(peak, static_cast<double>(bench::heapPeak() - before));
    }
    state.counters["peak_x_float_map"] = peak / (4.0 * size * size);
    state.counters["cpu_all_threads_s"] = cpu / static_cast<double>(state.iterations());
    state.SetLabel(state.range(1) == 0 ? "noise" : "bricks");
}

void Normal(benchmark::State& state) {
    run(state, [](const HeightField& f) {
        NormalBakeOptions o;
        o.filter = NormalFilter::Sobel;
        benchmark::DoNotOptimize(bakeNormalMap(f, o));
    });
}
void Cone(benchmark::State& state) {
    run(state, [](const HeightField& f) {
        benchmark::DoNotOptimize(bakeConeMap(f, WrapMode::Repeat, ConeKind::Conservative));
    });
}
void RelaxedCone(benchmark::State& state) {
    run(state, [](const HeightField& f) {
        benchmark::DoNotOptimize(bakeConeMap(f, WrapMode::Repeat, ConeKind::Relaxed));
    });
}
void ConeBruteForce(benchmark::State& state) {
    run(state, [](const HeightField& f) {
        benchmark::DoNotOptimize(bakeConservativeConesBruteForce(f, WrapMode::Repeat));
    });
}
void RelaxedConeBruteForce(benchmark::State& state) {
    run(state, [](const HeightField& f) {
        benchmark::DoNotOptimize(bakeRelaxedConesBruteForce(f, WrapMode::Repeat));
    });
}

// Ambient occlusion at the default settings (unlimited distance, the default azimuths) and with
// the artist's spread --distance 0.1 (issue 41's targets are 2048²; see docs/bakers.md).
void AmbientOcclusion(benchmark::State& state) {
    const double distance = state.range(2) == 0 ? std::numeric_limits<double>::infinity() : 0.1;
    run(state, [distance](const HeightField& f) {
        OcclusionBakeOptions o;
        o.distance = distance;
        benchmark::DoNotOptimize(bakeOcclusion(f, o, OcclusionOutputs::AmbientOcclusion));
    });
}

// A height map integrated from a normal map (a normal-only texture set's import), against the
// normal bake of the same size in the same run.
void HeightFromNormalMap(benchmark::State& state) {
    const int size = static_cast<int>(state.range(0));
    const Image normals =
        *bakeNormalMap(mapFor(static_cast<int>(state.range(1)), size), NormalBakeOptions{});
    run(state,
        [&normals](const HeightField&) { benchmark::DoNotOptimize(heightFromNormals(normals)); });
}

void sizes(benchmark::internal::Benchmark* b, int size, int iterations) {
    b->Args({size, 0})
        ->Args({size, 1})
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(iterations);
}

BENCHMARK(Normal)->Apply([](auto* b) { sizes(b, 4096, 3); });
BENCHMARK(Normal)->Apply([](auto* b) { sizes(b, 2048, 3); });
BENCHMARK(HeightFromNormalMap)->Apply([](auto* b) { sizes(b, 2048, 2); });
BENCHMARK(Cone)->Apply([](auto* b) { sizes(b, 1024, 3); });
BENCHMARK(RelaxedCone)->Apply([](auto* b) { sizes(b, 1024, 1); });
BENCHMARK(Cone)->Apply([](auto* b) { sizes(b, 256, 5); });
BENCHMARK(ConeBruteForce)->Apply([](auto* b) { sizes(b, 256, 1); });
BENCHMARK(RelaxedCone)->Apply([](auto* b) { sizes(b, 256, 3); });
BENCHMARK(RelaxedConeBruteForce)->Apply([](auto* b) { sizes(b, 256, 1); });
BENCHMARK(AmbientOcclusion)
    ->ArgsProduct({{256, 512}, {0, 1}, {0, 1}})
    ->ArgNames({"size", "map", "D0.1"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// Keeps every run's time, to print the fast/brute ratios of one run.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            times[r.benchmark_name()] = r.GetAdjustedRealTime();
            auto cpu = r.counters.find("cpu_all_threads_s");
            cpus[r.benchmark_name()] =
                cpu == r.counters.end() ? 0.0 : static_cast<double>(cpu->second);
        }
        ConsoleReporter::ReportRuns(runs);
    }
    std::map<std::string, double> times, cpus;
};

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    std::printf("threads: %u\n", std::thread::hardware_concurrency());
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    for (const char* map : {"0", "1"}) {
        for (auto [fast, brute] :
             {std::pair{"Cone", "ConeBruteForce"}, {"RelaxedCone", "RelaxedConeBruteForce"}}) {
            const std::string suffix = std::string("/256/") + map + "/iterations:";
            auto find = [&](const std::map<std::string, double>& values,
                            const std::string& name) -> double {
                for (const auto& [key, value] : values) {
                    if (key.rfind(name + suffix, 0) == 0)
                        return value;
                }
                return 0;
            };
            const double f = find(reporter.times, fast), b = find(reporter.times, brute);
            const double fc = find(reporter.cpus, fast), bc = find(reporter.cpus, brute);
            if (f > 0 && b > 0)
                std::printf("%s 256² (%s): brute force %.0f ms, fast %.1f ms: %.1fx faster (CPU "
                            "time: %.1fx)\n",
                            fast, map[0] == '0' ? "noise" : "bricks", b, f, b / f,
                            fc > 0 ? bc / fc : 0.0);
        }
    }
    benchmark::Shutdown();
    return 0;
}

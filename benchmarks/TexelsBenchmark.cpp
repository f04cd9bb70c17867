// Writing a 4096² map texel by texel through Image::at(), and through Image::writer() (the bakers'
// and loaders' way) against through one pointer, in the same run: the ratios printed at the end are
// what the copy-on-write test costs a write (SharedTexels.h), against the pointer loop as the
// compiler vectorises it and against the same loop kept scalar (no accessor with a test per write
// can be vectorised). Single-threaded. On a shared machine take the best of several runs
// (--benchmark_repetitions).
//
//   parallax-bench-texels

#include "parallax/image/Image.h"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <cstdio>
#include <map>
#include <string>

using namespace px;

namespace {

constexpr int kSide = 4096;

void FillThroughAt(benchmark::State& state) {
    Image image(kSide, kSide, 1);
    for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark's loop
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x)
                image.at(x, y) = static_cast<float>(x ^ y);
        benchmark::DoNotOptimize(image.pixels.data());
        benchmark::ClobberMemory();
    }
}

// The bulk writers' way: ImageWriter (Image.h), the texels made the image's own once.
void FillThroughWriter(benchmark::State& state) {
    Image image(kSide, kSide, 1);
    for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark's loop
        const ImageWriter put = image.writer();
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x)
                put.at(x, y) = static_cast<float>(x ^ y);
        benchmark::DoNotOptimize(put.texels);
        benchmark::ClobberMemory();
    }
}

void FillThroughPointer(benchmark::State& state) {
    Image image(kSide, kSide, 1);
    for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark's loop
        float* texels = image.pixels.data();
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x)
                texels[static_cast<std::size_t>(y) * kSide + x] = static_cast<float>(x ^ y);
        benchmark::DoNotOptimize(texels);
        benchmark::ClobberMemory();
    }
}

// The same loop, not vectorised (GCC's per-function optimisation attribute).
__attribute__((optimize("no-tree-vectorize"))) void
FillThroughPointerScalar(benchmark::State& state) {
    Image image(kSide, kSide, 1);
    for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark's loop
        float* texels = image.pixels.data();
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x)
                texels[static_cast<std::size_t>(y) * kSide + x] = static_cast<float>(x ^ y);
        benchmark::DoNotOptimize(texels);
        benchmark::ClobberMemory();
    }
}

BENCHMARK(FillThroughAt)->Unit(benchmark::kMillisecond);
BENCHMARK(FillThroughWriter)->Unit(benchmark::kMillisecond);
BENCHMARK(FillThroughPointer)->Unit(benchmark::kMillisecond);
BENCHMARK(FillThroughPointerScalar)->Unit(benchmark::kMillisecond);

class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            if (r.run_type != Run::RT_Iteration)
                continue;
            double& b = best[r.run_name.function_name];
            b = b > 0 ? std::min(b, r.GetAdjustedCPUTime()) : r.GetAdjustedCPUTime();
        }
        ConsoleReporter::ReportRuns(runs);
    }
    std::map<std::string, double> best; // per benchmark, the least CPU time of its runs
};

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const double at = reporter.best["FillThroughAt"];
    const double pointer = reporter.best["FillThroughPointer"];
    const double scalar = reporter.best["FillThroughPointerScalar"];
    const double writer = reporter.best["FillThroughWriter"];
    if (at > 0 && pointer > 0 && scalar > 0 && writer > 0)
        std::printf("4096² fill, ms of CPU (best run): through at() %.1f; through a pointer %.1f "
                    "(at() %.2fx), the same kept scalar %.1f (at() %.2fx); through writer() "
                    "%.1f (%.2fx the pointer)\n",
                    at, pointer, at / pointer, scalar, at / scalar, writer, writer / pointer);
    benchmark::Shutdown();
    return 0;
}

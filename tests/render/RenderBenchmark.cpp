// Frame time per technique at 512 x 512 and 1920 x 1080: the built-in bricks (512 x 512 heights,
// procedural albedo, height-derived normals, Blinn-Phong) on a plane filling the frame, seen at 55
// degrees from the normal. Each frame is timed alone: a steady clock around glFinish on llvmpipe,
// a GL timer query on real GPUs (FrameTimer.h). Compilation and bakes happen before timing.
// The table at the end gives each technique's median against `none` measured in the same run.
//   render-bench [--benchmark_filter=512] [--benchmark_repetitions=N]   (N > 1: medians)

#include "FrameTimer.h"
#include "RenderTestSupport.h"
#include "Renderer.h"

#include <benchmark/benchmark.h>
#include <cstdio>
#include <map>
#include <set>

using namespace px;

namespace {

struct Bench {
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<GpuMaterial> gpu;
};

Bench& bench() {
    static Bench b = [] {
        Bench made;
        if (!test::glContext()) {
            std::fprintf(stderr, "no OpenGL 4.3 context\n");
            std::exit(1);
        }
        made.renderer = Renderer::create().value();
        made.gpu = GpuMaterial::create(test::bricksAssets(512), WrapMode::Repeat).value();
        return made;
    }();
    return b;
}

void frame(benchmark::State& state, Technique technique, glm::ivec2 size) {
    Bench& b = bench();
    Result<RenderTarget> target = RenderTarget::create(size, TargetFormat::Rgba8);
    if (!target) {
        state.SkipWithError(target.error().message.c_str());
        return;
    }
    Material m = test::sampleMaterial(technique);
    OrbitCamera camera;
    camera.azimuthDeg = 20.0f;
    camera.elevationDeg = 35.0f;
    camera.distance = 1.9f;
    target->bind();
    auto draw = [&] { (void)b.renderer->draw(*b.gpu, m, camera, {}, {}, size); };
    timeFrames(draw, 1, 1, b.renderer->glInfo()); // compile, bake, first-use costs
    for (auto _ : state) {
        const FrameTiming t = timeFrames(draw, 1, 0, b.renderer->glInfo());
        state.SetIterationTime(t.medianMs / 1000.0);
    }
    state.SetLabel(timeFrames(draw, 1, 0, b.renderer->glInfo()).method() + ", " +
                   b.renderer->glInfo().renderer);
}

// Collects each benchmark's mean frame time for the ratio table.
class Collector : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> ms;
    std::set<std::string> medians;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            if (r.error_occurred)
                continue;
            // With --benchmark_repetitions the median of the repetitions, else the one run.
            const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
            if (r.run_type != Run::RT_Iteration && !median)
                continue;
            // "pom/512x512/min_time:0.500/manual_time" -> "pom/512x512"
            const std::string name = r.benchmark_name();
            const std::string key = name.substr(0, name.find('/', name.find('/') + 1));
            if (median || !medians.count(key))
                ms[key] = r.GetAdjustedRealTime();
            if (median)
                medians.insert(key);
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::pair<std::string, glm::ivec2>> sizes{{"512x512", {512, 512}},
                                                                {"1920x1080", {1920, 1080}}};
    for (const auto& [sizeName, size] : sizes) {
        for (const TechniqueInfo& t : allTechniques()) {
            const Technique id = t.id;
            const glm::ivec2 s = size;
            benchmark::RegisterBenchmark((std::string(t.name) + "/" + sizeName).c_str(),
                                         [id, s](benchmark::State& state) { frame(state, id, s); })
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond)
                ->MinTime(0.5);
        }
    }
    benchmark::Initialize(&argc, argv);
    Collector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);
    std::printf("\nframe time against none, same run:\n%-14s", "technique");
    for (const auto& [sizeName, size] : sizes)
        std::printf(" %22s", sizeName.c_str());
    std::printf("\n");
    for (const TechniqueInfo& t : allTechniques()) {
        std::printf("%-14s", t.name.data());
        for (const auto& [sizeName, size] : sizes) {
            const auto it = collector.ms.find(std::string(t.name) + "/" + sizeName);
            const auto base = collector.ms.find("none/" + sizeName);
            if (it == collector.ms.end() || base == collector.ms.end())
                std::printf(" %22s", "-");
            else
                std::printf(" %10.1f ms %7.2fx", it->second, it->second / base->second);
        }
        std::printf("\n");
    }
    return 0;
}

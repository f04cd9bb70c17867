// Frame time per technique and kernel flavour at 512 x 512 and 1920 x 1080: the built-in bricks
// (512 x 512 heights, procedural albedo, height-derived normals, Blinn-Phong) on a plane filling
// the frame, seen at 55 degrees from the normal. Each frame is timed alone: a steady clock around
// glFinish on llvmpipe, a GL timer query on real GPUs (FrameTimer.h). Compilation and bakes happen
// before timing. The table at the end gives each technique's median against `none` and the
// production kernels' against the verify kernels', all measured in the same run.
//   render-bench [--sizes=WxH,...] [--csv=FILE] [--min-time=SECONDS] [--map-size=N]
//                [--benchmark_filter=512] [--benchmark_repetitions=N]   (N > 1: medians)
// --min-time (default 0.5) and --map-size (default 512) smaller: a quick run that only shows it
// works (benchmarks/gpu-report.sh --quick, the ctest).

#include "RenderTestSupport.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/render/FrameTimer.h"
#include "parallax/render/Renderer.h"

#include <benchmark/benchmark.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <sstream>

using namespace px;

namespace {

struct Bench {
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<GpuMaterial> gpu;
};

int gMapSize = 512; // --map-size: the bricks' height map, baked before the first benchmark

Bench& bench() {
    static Bench b = [] {
        Bench made;
        if (!test::glContext()) {
            std::fprintf(stderr, "no OpenGL 4.3 context\n");
            std::exit(1);
        }
        made.renderer = Renderer::create().value();
        made.gpu = GpuMaterial::create(test::bricksAssets(gMapSize), WrapMode::Repeat).value();
        return made;
    }();
    return b;
}

void frame(benchmark::State& state, Technique technique, KernelFlavour kernels, glm::ivec2 size) {
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
    DrawOptions options;
    options.kernels = kernels;
    auto draw = [&] { (void)b.renderer->draw(*b.gpu, m, camera, {}, options, size); };
    timeFrames(draw, 1, 1, b.renderer->glInfo()); // compile, bake, first-use costs
    for (auto _ : state) { // NOLINT(clang-analyzer-deadcode.DeadStores): the loop idiom
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
            // "pom/production/512x512/min_time:0.500/manual_time" -> "pom/production/512x512"
            const std::string name = r.benchmark_name();
            const std::size_t second = name.find('/', name.find('/') + 1);
            const std::string key = name.substr(0, name.find('/', second + 1));
            if (median || !medians.count(key))
                ms[key] = r.GetAdjustedRealTime();
            if (median)
                medians.insert(key);
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

// "WxH,WxH" into named sizes; empty on a malformed list.
std::vector<std::pair<std::string, glm::ivec2>> parseSizes(const std::string& text) {
    std::vector<std::pair<std::string, glm::ivec2>> sizes;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');) {
        int w = 0, h = 0;
        char x = 0;
        std::stringstream one(part);
        if (!(one >> w >> x >> h) || x != 'x' || w < 1 || h < 1 || !one.eof())
            return {};
        sizes.emplace_back(part, glm::ivec2(w, h));
    }
    return sizes;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::pair<std::string, glm::ivec2>> sizes{{"512x512", {512, 512}},
                                                          {"1920x1080", {1920, 1080}}};
    std::string csvPath;
    double minTime = 0.5;
    // Our own options first; the rest goes to Google Benchmark.
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--sizes=", 8) == 0) {
            sizes = parseSizes(argv[i] + 8);
            if (sizes.empty()) {
                std::fprintf(stderr, "error: --sizes=%s is not WxH[,WxH...]\n", argv[i] + 8);
                return 2;
            }
        } else if (std::strncmp(argv[i], "--csv=", 6) == 0) {
            csvPath = argv[i] + 6;
        } else if (std::strncmp(argv[i], "--min-time=", 11) == 0) {
            char* end = nullptr;
            minTime = std::strtod(argv[i] + 11, &end);
            if (*end != '\0' || !(minTime > 0.0 && minTime <= 60.0)) {
                std::fprintf(stderr, "error: --min-time=%s is not seconds in (0, 60]\n",
                             argv[i] + 11);
                return 2;
            }
        } else if (std::strncmp(argv[i], "--map-size=", 11) == 0) {
            char* end = nullptr;
            const long n = std::strtol(argv[i] + 11, &end, 10);
            if (*end != '\0' || n < 16 || n > 8192) {
                std::fprintf(stderr, "error: --map-size=%s is not a size 16..8192\n", argv[i] + 11);
                return 2;
            }
            gMapSize = static_cast<int>(n);
        } else {
            argv[kept++] = argv[i];
        }
    }
    argc = kept;
    const KernelFlavour flavours[] = {KernelFlavour::Production, KernelFlavour::Verify};
    auto key = [](const TechniqueInfo& t, KernelFlavour f, const std::string& size) {
        return std::string(t.name) + "/" + std::string(shader::kernelFlavourName(f)) + "/" + size;
    };
    for (const auto& [sizeName, size] : sizes) {
        for (const TechniqueInfo& t : allTechniques()) {
            for (KernelFlavour f : flavours) {
                const Technique id = t.id;
                const glm::ivec2 s = size;
                benchmark::RegisterBenchmark(
                    key(t, f, sizeName).c_str(),
                    [id, f, s](benchmark::State& state) { frame(state, id, f, s); })
                    ->UseManualTime()
                    ->Unit(benchmark::kMillisecond)
                    ->MinTime(minTime);
            }
        }
    }
    benchmark::Initialize(&argc, argv);
    Collector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);
    std::printf("\nframe time, production kernels, against none and against the verify kernels "
                "(same run):\n%-14s",
                "technique");
    for (const auto& [sizeName, size] : sizes)
        std::printf(" %38s", sizeName.c_str());
    std::printf("\n");
    std::string csv = "technique,size,production_ms,verify_ms,production_vs_none,"
                      "production_vs_verify,renderer\n";
    const std::string renderer = bench().renderer->glInfo().renderer;
    auto find = [&](const std::string& k) {
        const auto it = collector.ms.find(k);
        return it == collector.ms.end() ? -1.0 : it->second;
    };
    for (const TechniqueInfo& t : allTechniques()) {
        std::printf("%-14s", t.name.data());
        for (const auto& [sizeName, size] : sizes) {
            const double production = find(key(t, KernelFlavour::Production, sizeName));
            const double verify = find(key(t, KernelFlavour::Verify, sizeName));
            const double none =
                find(key(info(Technique::None), KernelFlavour::Production, sizeName));
            if (production < 0.0 || verify < 0.0 || none <= 0.0) {
                std::printf(" %38s", "-");
                continue;
            }
            std::printf(" %10.1f ms %7.2fx none %7.3fx verify", production, production / none,
                        production / verify);
            char row[256];
            std::snprintf(row, sizeof row, "%s,%s,%.3f,%.3f,%.4f,%.4f,\"%s\"\n", t.name.data(),
                          sizeName.c_str(), production, verify, production / none,
                          production / verify, renderer.c_str());
            csv += row;
        }
        std::printf("\n");
    }
    if (!csvPath.empty()) {
        if (Status written = writeTextFile(csvPath, csv); !written) {
            std::fprintf(stderr, "error: %s\n", written.error().message.c_str());
            return 1;
        }
    }
    return 0;
}

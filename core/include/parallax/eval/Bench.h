#pragma once
// The benchmark behind `parallax-cli bench` and the editor's Compare panel: every technique over a
// sweep of its quality settings on the canonical trace scene (docs/conventions.md §5), measured
// against `exact` on the same rays. Errors and fetches are deterministic; times are measured,
// reported, never asserted.
//
// Threading: runBench() is a pure function of its config (no global state) and may run on any
// thread; it reports progress and polls for cancellation through an EvalControl.

#include "parallax/Result.h"
#include "parallax/eval/EvalControl.h"
#include "parallax/eval/HitErrorStats.h"
#include "parallax/eval/QualitySweep.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/trace/Tracer.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace px {

struct BenchMap {
    std::string name; // as reported: the file name given, or the material's name
    std::shared_ptr<const HeightField> field;
};

// What a GPU timer is asked to time: the canonical scene at one angle with one technique and
// setting, over as many rays as a `width` x `height` frame has pixels. `maps` holds the height
// field and the derived maps the bench already baked (so the timer need not bake them again).
struct GpuFrameRequest {
    TraceMaps maps;
    const BenchSetting* setting = nullptr;
    float scale = 0.0f;
    double polarDeg = 0.0;
    double azimuthDeg = 0.0;
    int width = 1920;
    int height = 1080;
};

struct GpuFrameTiming {
    double msPerFrame = 0.0; // steady clock around the frame and glFinish, or a timer query
    std::string renderer;    // GL_RENDERER, marked as software where it is (llvmpipe)
};

// Supplied by the application (the core has no GL); an error leaves the GPU column empty with
// the error's sentence as the reason.
using GpuFrameTimer = std::function<Result<GpuFrameTiming>(const GpuFrameRequest&)>;

// The view angles the bench measures unless told otherwise (CLI, editor and README alike).
inline const std::vector<double> kBenchPolarDeg{30.0, 60.0, 80.0, 87.0};

struct BenchConfig {
    std::vector<BenchMap> maps;
    WrapMode wrap = WrapMode::Repeat;
    std::vector<BenchSetting> settings; // e.g. qualitySweep() of each technique
    std::vector<double> polarDeg = kBenchPolarDeg;
    double azimuthDeg = 35.0;
    std::vector<float> scales{0.05f, 0.1f};
    int rays = 128; // R: R x R rays per map, scale and angle
    // CPU time: each setting's rays are traced this many times on one thread and the fastest pass
    // is reported (the first pass also gives the hits). 0: no CPU timing, hits traced in parallel.
    int timingRepeats = 1;
    GpuFrameTimer gpuTimer;     // empty: no GPU timing
    std::string gpuUnavailable; // why there is no timer, reported in place of the timings
};

struct BenchRow {
    std::string map; // "all" for a pooled row
    int width = 0;   // 0 for a pooled row
    int height = 0;
    std::optional<float> scale; // empty for a pooled row (every scale)
    double polarDeg = 0.0;
    BenchSetting setting;
    HitErrorStats stats;
    std::optional<double> cpuNsPerRay;   // one thread
    std::optional<double> gpuMsPerFrame; // mean over the pooled conditions for a pooled row
    std::string gpuRenderer;             // the renderer that timed it, or why the timing is missing
    bool pooled = false;
};

struct BenchReport {
    WrapMode wrap = WrapMode::Repeat;
    double azimuthDeg = 35.0;
    int rays = 128;
    std::vector<double> polarDeg;
    std::vector<BenchRow> rows;   // one per polar angle, setting, map and scale
    std::vector<BenchRow> pooled; // one per polar angle and setting: every map and scale's rays
    std::string gpuNote;          // the renderer used, or why there are no GPU timings
};

// Fails with a sentence naming the problem: no maps, an empty map, no settings, an invalid
// parameter set, a polar angle outside [0, 90), a negative or non-finite scale, an angle or scale
// listed twice, rays outside [1, 4096], repeats outside [0, 100].
Status validate(const BenchConfig& config);

// Progress units: one per derived map baked, per exact reference traced, and per setting traced
// on each map and scale. Errors: validate()'s, a tracer that cannot be created (naming the map),
// evaluationCancelled().
Result<BenchReport> runBench(const BenchConfig& config, const EvalControl& control = {});

// A row (per condition or pooled) of a technique documented exact (isDocumentedExact) with a ray
// further than kExactTexels from the reference fails: one sentence per such row, naming the
// setting, the condition and the worst error. Empty when every documented promise held.
std::vector<std::string> exactnessFailures(const BenchReport& report);

} // namespace px

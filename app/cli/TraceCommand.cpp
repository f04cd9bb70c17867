// parallax-cli trace: the canonical scene of docs/conventions.md §5 with one technique, as CSV.

#include "Cli.h"
#include "CommonOptions.h"
#include "parallax/eval/HitErrorStats.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/render/GpuTracer.h"
#include "parallax/trace/ParallaxBound.h"
#include "parallax/trace/TraceScene.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace px::cli {

namespace {

struct TraceOptions {
    HeightOptions height;
    float scale = 0.05f;
    double polar = 45.0;
    double azimuth = 0.0;
    int rays = 64;
    std::string technique = "exact";
    QualityOptions quality;
    std::string out;
    bool gpu = false;
    KernelOptions kernels;
};

std::vector<std::string> techniqueNames() {
    std::vector<std::string> names;
    for (const TechniqueInfo& t : allTechniques())
        names.emplace_back(t.name);
    return names;
}

// What the GPU kernels' hits cost in accuracy beside the CPU's: both against the CPU's exact
// reference for the same rays (the error of what the GPU draws, hardware filtering included).
std::string gpuSummary(const TraceOptions& o, const TraceMaps& maps, const Tracer& cpu,
                       const TraceScene& scene, const std::vector<TraceResult>& gpuHits,
                       const GpuTraceTiming& timing) {
    Result<Tracer> exact =
        Tracer::create(maps, Technique::Exact, info(Technique::Exact).defaults, o.scale);
    if (!exact)
        return "no error summary: " + exact.error().message;
    const std::vector<TraceResult> reference = traceScene(*exact, scene);
    const std::vector<TraceResult> cpuHits = traceScene(cpu, scene);
    // Most GPUs filter with 8-bit weights, llvmpipe with finer ones: the CPU model says what 8 bits
    // cost on the same rays.
    Tracer eightBit = cpu;
    eightBit.modelTextureUnit(8);
    const std::vector<TraceResult> modelHits = traceScene(eightBit, scene);
    const int w = maps.height->width, h = maps.height->height;
    const HitErrorStats g = measureHits(gpuHits, reference, w, h);
    const HitErrorStats c = measureHits(cpuHits, reference, w, h);
    const HitErrorStats m = measureHits(modelHits, reference, w, h);
    char line[640];
    std::snprintf(line, sizeof line,
                  "GPU (%s kernels, %s): p99 error %.4g texels, mean %.4g, max %.4g, %.2f fetches "
                  "per ray; CPU: p99 %.4g, mean %.4g, max %.4g, %.2f fetches; production kernels "
                  "with 8-bit filter weights (CPU model): p99 %.4g, mean %.4g, max %.4g\n",
                  o.kernels.name.c_str(), timing.renderer.c_str(), g.p99Error, g.meanError,
                  g.maxError, g.meanFetches, c.p99Error, c.meanError, c.maxError, c.meanFetches,
                  m.p99Error, m.meanError, m.maxError);
    return line;
}

int runTrace(const TraceOptions& o) {
    const Technique technique = *parseTechnique(o.technique);
    TraceParams params = info(technique).defaults;
    o.quality.applyTo(params);

    TraceScene scene;
    scene.rays = o.rays;
    scene.polarDeg = o.polar;
    scene.azimuthDeg = o.azimuth;
    if (Status s = validate(scene); !s)
        return fail(s.error().message);
    if (const BoundedParallax b = boundParallax(parallaxVector(o.scale, o.polar, o.azimuth));
        !b.note.empty())
        std::cerr << "note: " << b.note << "\n";

    Result<HeightField> field = o.height.load();
    if (!field)
        return fail(field.error().message);
    TraceMaps maps;
    maps.height = &*field;
    maps.wrap = o.height.wrapMode();
    Result<Tracer> tracer = Tracer::create(maps, technique, params, o.scale);
    if (!tracer)
        return fail(tracer.error().message);

    std::vector<TraceResult> results;
    std::string summary;
    if (o.gpu) {
        GpuTraceTiming timing;
        Result<std::vector<TraceResult>> gpu = traceSceneHeadless(
            maps, technique, params, o.scale, scene, &timing, o.kernels.flavour());
        if (!gpu)
            return fail(gpu.error().message);
        results = std::move(*gpu);
        summary = gpuSummary(o, maps, *tracer, scene, results, timing);
    } else {
        results = traceScene(*tracer, scene);
    }
    const std::string csv = traceCsv(scene, results);
    if (o.out == "-") {
        std::cout << csv << std::flush;
        std::cerr << summary; // after the CSV, which may be piped on
        return 0;
    }
    if (Status s = writeTextFile(o.out, csv); !s)
        return fail(s.error().message);
    std::cout << summary;
    return 0;
}

} // namespace

Action addTraceCommand(CLI::App& app) {
    auto o = std::make_shared<TraceOptions>();
    CLI::App* cmd = app.add_subcommand(
        "trace", "Trace the canonical scene (R x R rays, one direction) and write each hit as CSV");
    o->height.addTo(*cmd);
    cmd->add_option("--scale", o->scale, "Height scale s in uv units (depth of h = 0)")
        ->check(inRange(0.0, 100.0));
    cmd->add_option("--polar", o->polar, "View angle from the normal, degrees [0, 90)")
        ->check(inRange(0.0, 89.999));
    cmd->add_option("--azimuth", o->azimuth, "View azimuth from +u towards +v, degrees")
        ->check(inRange(-360.0, 360.0));
    cmd->add_option("--rays", o->rays, "Rays per side (R)")->check(inRange(1, 4096));
    cmd->add_option("--technique", o->technique, "Technique")
        ->check(CLI::IsMember(techniqueNames()));
    o->quality.addTo(*cmd);
    cmd->add_flag("--gpu", o->gpu,
                  "Trace on the GPU (headless OpenGL 4.3, the same kernels): same CSV, and a "
                  "line comparing the GPU's and the CPU's errors against the exact hits");
    o->kernels.addTo(*cmd);
    cmd->add_option("--out", o->out, "Output CSV (i,j,u,v,t,fetches); - for standard output")
        ->required();
    return [o] { return runTrace(*o); };
}

} // namespace px::cli

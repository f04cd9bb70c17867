// parallax-cli bench: every technique over a sweep of its quality settings on the canonical scene,
// measured against `exact` (core/include/parallax/eval/Bench.h), as CSV and a work-precision plot.

#include "Cli.h"
#include "CommonOptions.h"
#include "WorkPrecisionPlot.h"
#include "parallax/eval/BenchCsv.h"
#include "parallax/eval/WorkPrecision.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/render/GpuBenchTimer.h"
#include "parallax/render/GpuTracer.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/ParallaxBound.h"
#include "parallax/trace/TraceScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>
#include <unistd.h>

namespace px::cli {

namespace {

struct BenchOptions {
    std::vector<std::string> heights;
    std::vector<std::string> samples;
    int sampleSize = 128;
    bool invert = false;
    bool normalize = false;
    std::string channel = "red";
    std::string wrap = "repeat";
    std::string techniques = "all";
    std::vector<std::string> sweeps;
    bool defaultsOnly = false;
    std::vector<double> polar = kBenchPolarDeg;
    double azimuth = 35.0;
    std::vector<float> scales{0.05f, 0.1f};
    int rays = 128;
    int repeats = 1;
    bool gpu = false;
    int gpuFrames = 1;
    int gpuRays = 1440;
    KernelOptions kernels;
    std::string out;
    std::string plot;
    std::string fromCsv;
    bool quiet = false;
};

// The processor model and hardware threads, for the report (Linux; "unknown CPU" elsewhere).
std::string machineName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    }
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " threads";
}

Result<std::vector<BenchMap>> loadMaps(const BenchOptions& o) {
    std::vector<BenchMap> maps;
    HeightLoadOptions load;
    load.channel = parseHeightChannel(o.channel).value_or(HeightChannel::Red);
    load.invert = o.invert;
    load.normalize = o.normalize;
    for (const std::string& file : o.heights) {
        Result<HeightField> field = loadHeightField(file, load);
        if (!field)
            return field.error();
        maps.push_back({file, std::make_shared<HeightField>(std::move(*field))});
    }
    for (const std::string& name : o.samples) {
        const ProceduralMap kind = *parseProceduralMap(name);
        maps.push_back(
            {name + " " + std::to_string(o.sampleSize),
             std::make_shared<HeightField>(makeProceduralMap(kind, o.sampleSize, o.sampleSize))});
    }
    if (maps.empty())
        return Error{"give at least one height map (--height FILE or --sample NAME)"};
    return maps;
}

void printSummary(std::ostream& out, const BenchReport& report) {
    const bool gpu = std::any_of(report.pooled.begin(), report.pooled.end(),
                                 [](const BenchRow& r) { return r.gpuMsPerFrame.has_value(); });
    char line[256];
    std::snprintf(line, sizeof line, "%-13s %-24s %6s %10s %10s %10s %9s %9s %10s%s\n", "technique",
                  "setting", "polar", "mean err", "p99 err", "max err", "wrong", "fetches",
                  "ns/ray", gpu ? "   GPU ms  GPU p99 err  GPU fetches" : "");
    out << line;
    for (const BenchRow& row : report.pooled) {
        const std::string ns =
            row.cpuNsPerRay ? std::to_string(std::lround(*row.cpuNsPerRay)) : "-";
        char ms[64] = "";
        if (gpu)
            std::snprintf(ms, sizeof ms, " %9.1f %12.4g %12.2f", row.gpuMsPerFrame.value_or(NAN),
                          row.gpuStats ? row.gpuStats->p99Error : NAN,
                          row.gpuStats ? row.gpuStats->meanFetches : NAN);
        std::snprintf(
            line, sizeof line, "%-13s %-24s %6g %10.4g %10.4g %10.4g %9lld %9.2f %10s%s\n",
            info(row.setting.technique).name.data(), row.setting.label.c_str(), row.polarDeg,
            row.stats.meanError, row.stats.p99Error, row.stats.maxError,
            static_cast<long long>(row.stats.wrongSurface), row.stats.meanFetches, ns.c_str(), ms);
        out << line;
    }
}

std::string joinedScales(const std::vector<float>& scales) {
    std::string text;
    char number[32];
    for (float s : scales) {
        std::snprintf(number, sizeof number, "%g", s);
        text += (text.empty() ? "" : ", ") + std::string(number);
    }
    return text;
}

Status writePlot(const BenchOptions& o, const BenchReport& report, const std::string& what) {
    PlotLabels labels;
    labels.title = "Work-precision: p99 hit error against cost, " + std::to_string(report.rays) +
                   "\xc2\xb2 rays per map and scale, azimuth " +
                   std::to_string(std::lround(report.azimuthDeg)) + "\xc2\xb0";
    labels.subtitle = what + (report.gpuNote.empty() ? "" : "; GPU: " + report.gpuNote);
    return writeWorkPrecisionPlot(o.plot, makeWorkPrecisionChart(report), labels);
}

// Plots a report measured before, without measuring again.
int replot(const BenchOptions& o) {
    if (o.plot.empty())
        return fail("--from-csv only plots: give --plot FILE.svg");
    Result<std::string> text = readTextFile(o.fromCsv);
    if (!text)
        return fail(text.error().message);
    Result<BenchReport> report = parseBenchCsv(*text, o.fromCsv);
    if (!report)
        return fail(report.error().message);
    if (Status s = writePlot(o, *report, "from " + o.fromCsv); !s)
        return fail(s.error().message);
    return 0;
}

int runBenchCommand(const BenchOptions& o) {
    if (!o.fromCsv.empty())
        return replot(o);
    if (o.out.empty())
        return fail("give --out FILE.csv (or - for standard output)");
    // Every output is checked before measuring (the folders in Cli.cpp), not after minutes.
    if (!o.plot.empty() && std::filesystem::path(o.plot).extension() != ".svg")
        return fail(o.plot + ": the plot is written as SVG: name it .svg");
    Result<std::vector<Technique>> techniques = parseTechniqueList(o.techniques);
    if (!techniques)
        return fail(techniques.error().message);
    // Hand-given sweeps replace the built-in ones of their techniques (and add the technique);
    // read before any map, so a mistyped value costs no load.
    std::vector<std::pair<Technique, std::vector<BenchSetting>>> given;
    for (const std::string& spec : o.sweeps) {
        Result<std::vector<BenchSetting>> sweep = parseSweep(spec);
        if (!sweep)
            return fail(sweep.error().message);
        const Technique t = sweep->front().technique;
        if (std::find(techniques->begin(), techniques->end(), t) == techniques->end())
            techniques->push_back(t);
        given.emplace_back(t, std::move(*sweep));
    }
    Result<std::vector<BenchMap>> maps = loadMaps(o);
    if (!maps)
        return fail(maps.error().message);

    BenchConfig config;
    config.maps = std::move(*maps);
    config.wrap = parseWrapMode(o.wrap).value_or(WrapMode::Repeat);
    for (Technique t : *techniques) {
        std::vector<BenchSetting> sweep =
            o.defaultsOnly ? std::vector<BenchSetting>{defaultSetting(t)} : qualitySweep(t);
        bool replaced = false;
        for (auto& [technique, settings] : given) {
            if (technique == t) {
                sweep = replaced ? sweep : std::vector<BenchSetting>{};
                sweep.insert(sweep.end(), settings.begin(), settings.end());
                replaced = true;
            }
        }
        for (BenchSetting& s : sweep)
            config.settings.push_back(std::move(s));
    }
    config.polarDeg = o.polar;
    config.azimuthDeg = o.azimuth;
    config.scales = o.scales;
    config.rays = o.rays;
    config.timingRepeats = o.repeats;
    if (o.gpu) {
        GpuBenchOptions options;
        options.frames = o.gpuFrames;
        options.rays = o.gpuRays == 1440 ? 0 : o.gpuRays; // 1440^2: the frame itself
        options.kernels = o.kernels.flavour();
        Result<std::unique_ptr<GpuBenchTimer>> timer =
            GpuBenchTimer::create(options, headlessBenchContext);
        if (timer) {
            config.gpuTimer = [t = std::shared_ptr<GpuBenchTimer>(std::move(*timer))](
                                  const GpuFrameRequest& r) { return t->time(r); };
        } else {
            config.gpuUnavailable = timer.error().message;
        }
    } else {
        config.gpuUnavailable = "not requested (--gpu)";
    }
    if (Status s = validate(config); !s)
        return fail(s.error().message);
    for (double polar : config.polarDeg) {
        for (float scale : config.scales) {
            const BoundedParallax b =
                boundParallax(parallaxVector(scale, polar, config.azimuthDeg));
            if (!b.note.empty())
                std::cerr << "note: polar " << polar << ", scale " << scale << ": " << b.note
                          << "\n";
        }
    }

    // Progress on one rewritten line, only where someone watches it.
    const bool showProgress = !o.quiet && isatty(STDERR_FILENO);
    EvalControl control;
    if (showProgress) {
        control.progress = [](const EvalProgress& p) {
            std::fprintf(stderr, "\r\033[K[%d/%d] %s", p.done, p.total, p.stage.c_str());
            std::fflush(stderr);
        };
    }
    Result<BenchReport> report = runBench(config, control);
    if (showProgress)
        std::fprintf(stderr, "\r\033[K");
    if (!report)
        return fail(report.error().message);

    OutputBatch outputs; // the CSV and the plot, both or neither
    if (o.out != "-") {
        if (Status s = writeTextFile(o.out, benchCsv(*report)); !s)
            return fail(s.error().message);
    }
    const std::string machine = machineName();
    if (!o.plot.empty()) {
        std::string maps;
        for (const BenchMap& m : config.maps)
            maps += (maps.empty() ? "" : ", ") + m.name;
        const std::string what = "maps " + maps + "; scales " + joinedScales(config.scales) +
                                 "; CPU: " + machine + ", one thread";
        if (Status s = writePlot(o, *report, what); !s)
            return fail(s.error().message);
    }
    if (Status s = outputs.commit(); !s)
        return fail(s.error().message);
    if (o.out == "-")
        std::cout << benchCsv(*report);
    if (!o.quiet) {
        std::ostream& out = o.out == "-" ? std::cerr : std::cout;
        out << "CPU: " << machine << " (times: one thread, fastest of " << o.repeats << ")\n";
        if (!report->gpuNote.empty())
            out << "GPU: " << report->gpuNote << "\n";
        printSummary(out, *report);
    }
    // A technique documented exact that is not, on some ray, fails the run (the report is kept).
    const std::vector<std::string> failures = exactnessFailures(*report);
    for (const std::string& f : failures)
        std::cerr << "error: not exact: " << f << "\n";
    return failures.empty() ? 0 : 1;
}

} // namespace

Action addBenchCommand(CLI::App& app) {
    auto o = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Measure every technique and quality setting against the exact reference "
                 "(error, fetches, time) and write a CSV report and a work-precision plot");
    cmd->add_option("--height", o->heights, "Height maps (PNG, TIFF, EXR, BMP, JPEG, TGA)");
    std::vector<std::string> names(proceduralMapNames().begin(), proceduralMapNames().end());
    cmd->add_option("--sample", o->samples, "Built-in procedural maps to measure as well")
        ->delimiter(',')
        ->check(CLI::IsMember(names));
    cmd->add_option("--sample-size", o->sampleSize, "Side of the --sample maps in texels")
        ->check(inRange(1, 4096));
    cmd->add_flag("--invert", o->invert, "The files are depth maps (white = deep)");
    cmd->add_flag("--normalize", o->normalize, "Remap each map's [min, max] to [0, 1]");
    cmd->add_option("--channel", o->channel, "Channel holding the height")
        ->check(CLI::IsMember({"red", "green", "blue", "alpha", "luminance"}));
    cmd->add_option("--wrap", o->wrap, "Wrap mode of the material")
        ->check(CLI::IsMember({"repeat", "clamp"}));
    cmd->add_option("--techniques", o->techniques, "all, or a comma-separated list of techniques");
    cmd->add_option("--sweep", o->sweeps,
                    "A technique's settings by hand, replacing its built-in sweep: "
                    "TECHNIQUE:PARAMETER=V1,V2 (layers=8-32,16-64; binary-steps, secant-steps, "
                    "max-steps); repeatable");
    cmd->add_flag("--defaults-only", o->defaultsOnly,
                  "Measure each technique's default setting only, not its sweep");
    cmd->add_option("--polar", o->polar, "View angles from the normal, degrees [0, 90)")
        ->delimiter(',')
        ->check(inRange(0.0, 89.999));
    cmd->add_option("--azimuth", o->azimuth, "View azimuth from +u towards +v, degrees")
        ->check(inRange(-360.0, 360.0));
    cmd->add_option("--scales", o->scales, "Height scales s in uv units")
        ->delimiter(',')
        ->check(inRange(0.0, 100.0));
    cmd->add_option("--rays", o->rays, "Rays per side (R): R x R rays per map, scale and angle")
        ->check(inRange(1, 4096));
    cmd->add_option("--repeats", o->repeats,
                    "Timed single-thread passes per setting, fastest reported (0: no CPU timing)")
        ->check(inRange(0, 100));
    cmd->add_flag("--gpu", o->gpu,
                  "Also time each setting on the GPU: 1440x1440 = 1920x1080 rays of the scene, "
                  "traced by the GL kernels on a headless context");
    cmd->add_option("--gpu-frames", o->gpuFrames,
                    "Timed GPU traces per setting after one warm-up, fastest reported")
        ->check(inRange(1, 100));
    cmd->add_option("--gpu-rays", o->gpuRays,
                    "Rays per side of the timed GPU trace (1440: a 1920x1080 frame's pixels; "
                    "fewer are timed and scaled to the frame)")
        ->check(inRange(1, 4096));
    o->kernels.addTo(*cmd);
    cmd->add_option("--out", o->out, "Output CSV; - for standard output");
    cmd->add_option("--plot", o->plot, "Work-precision plot (.svg)");
    cmd->add_option("--from-csv", o->fromCsv,
                    "Plot a report written before (with --plot) instead of measuring");
    cmd->add_flag("--quiet", o->quiet, "No progress line and no summary table");
    return [o] { return runBenchCommand(*o); };
}

} // namespace px::cli

// parallax-cli bench-ao: the occlusion bakers' error against cost (parallax/eval/OcclusionBench.h)
// as CSV, a summary table and a plot, as `bench` does for the techniques.

#include "Cli.h"
#include "CommonOptions.h"
#include "DistanceOption.h"
#include "OcclusionPlot.h"
#include "parallax/eval/OcclusionBench.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/sample/ProceduralMaps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace px::cli {

namespace {

// The built-in samples and the adversarial maps the table of docs/bakers.md is measured on.
const std::vector<std::string> kDefaultSamples{
    "bricks", "stones", "rivets", "noise", "spike-flat", "walls", "pits", "terraces", "jpeg"};

struct BenchAoOptions {
    std::vector<std::string> heights;
    std::vector<std::string> samples; // none and no --height: kDefaultSamples
    int sampleSize = 128;
    std::string wrap = "repeat";
    float scale = 0.05f;
    double distance = 0.1;
    int referenceDirections = 1024;
    std::vector<std::string> methods;
    int repeats = 1;
    std::string out;
    std::string plot;
    bool quiet = false;
};

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

std::string distanceText(double d) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", d);
    return std::isfinite(d) ? std::string(text) + " uv" : "unlimited";
}

void printSummary(std::ostream& out, const OcclusionBenchReport& report) {
    char line[256];
    std::snprintf(line, sizeof line, "%-12s %-30s %9s %10s %10s %10s %12s\n", "method", "setting",
                  "samples", "mean", "p99.9", "max", "ns/texel");
    out << line;
    for (const OcclusionBenchRow& r : report.pooled) {
        std::snprintf(line, sizeof line, "%-12s %-30s %9g %10.3f %10.3f %10.3f %12.1f\n",
                      r.method.c_str(), r.setting.c_str(), r.samples, r.meanSteps, r.p999Steps,
                      r.maxSteps, r.nsPerTexel());
        out << line;
    }
}

int runBenchAo(const BenchAoOptions& o) {
    if (o.out.empty())
        return fail("give --out FILE.csv (or - for standard output)");
    if (!o.plot.empty() && std::filesystem::path(o.plot).extension() != ".svg")
        return fail(o.plot + ": the plot is written as SVG: name it .svg");
    OcclusionBenchConfig config;
    for (const std::string& file : o.heights) {
        Result<HeightField> field = loadHeightField(file);
        if (!field)
            return fail(field.error().message);
        config.maps.push_back({file, std::make_shared<HeightField>(std::move(*field))});
    }
    const bool defaults = o.heights.empty() && o.samples.empty();
    for (const std::string& name : defaults ? kDefaultSamples : o.samples) {
        config.maps.push_back({name + " " + std::to_string(o.sampleSize),
                               std::make_shared<HeightField>(makeProceduralMap(
                                   *parseProceduralMap(name), o.sampleSize, o.sampleSize))});
    }
    config.heightScale = o.scale;
    config.wrap = parseWrapMode(o.wrap).value_or(WrapMode::Repeat);
    config.distance = o.distance;
    config.referenceDirections = o.referenceDirections;
    config.repeats = o.repeats;
    for (OcclusionMethod& m : defaultOcclusionMethods(o.distance)) {
        if (o.methods.empty() ||
            std::find(o.methods.begin(), o.methods.end(), m.method) != o.methods.end())
            config.methods.push_back(std::move(m));
    }

    const bool showProgress = !o.quiet && isatty(STDERR_FILENO);
    EvalControl control;
    if (showProgress) {
        control.progress = [](const EvalProgress& p) {
            std::fprintf(stderr, "\r\033[K[%d/%d] %s", p.done, p.total, p.stage.c_str());
            std::fflush(stderr);
        };
    }
    Result<OcclusionBenchReport> report = runOcclusionBench(config, control);
    if (showProgress)
        std::fprintf(stderr, "\r\033[K");
    if (!report)
        return fail(report.error().message);
    const std::string csv = occlusionBenchCsv(*report);
    if (o.out == "-")
        std::cout << csv;
    else if (Status s = writeTextFile(o.out, csv); !s)
        return fail(s.error().message);
    const std::string machine = machineName();
    if (!o.plot.empty()) {
        std::ostringstream title, subtitle;
        title << "Ambient occlusion: error against the exact value (" << report->referenceDirections
              << " directions) and time";
        subtitle << config.maps.size() << " maps, height scale " << o.scale << ", distance "
                 << distanceText(o.distance) << ", " << o.wrap << "; " << machine
                 << ", every thread";
        if (Status s = writeOcclusionPlot(o.plot, *report, title.str(), subtitle.str()); !s)
            return fail(s.error().message);
    }
    if (!o.quiet) {
        std::ostream& out = o.out == "-" ? std::cerr : std::cout;
        out << "CPU: " << machine << " (times: every thread, fastest of " << o.repeats << ")\n"
            << "Error in 8-bit steps against the exact bake at " << report->referenceDirections
            << " directions, pooled over " << config.maps.size() << " maps, distance "
            << distanceText(o.distance) << "\n";
        printSummary(out, *report);
    }
    return 0;
}

} // namespace

Action addBenchAoCommand(CLI::App& app) {
    auto o = std::make_shared<BenchAoOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bench-ao", "Measure the ambient occlusion bakers (the exact one at several direction "
                    "counts, and the peers' methods) against the exact value: error in 8-bit "
                    "steps and time, as CSV, a table and a plot");
    cmd->add_option("--height", o->heights, "Height maps to measure on");
    std::vector<std::string> names(proceduralMapNames().begin(), proceduralMapNames().end());
    cmd->add_option("--sample", o->samples,
                    "Built-in maps (default, without --height: bricks, stones, rivets, noise and "
                    "the adversarial spike-flat, walls, pits, terraces, jpeg)")
        ->delimiter(',')
        ->check(CLI::IsMember(names));
    cmd->add_option("--sample-size", o->sampleSize, "Side of the --sample maps in texels")
        ->check(inRange(4, 2048));
    cmd->add_option("--wrap", o->wrap, "Wrap mode of the surface")
        ->check(CLI::IsMember({"repeat", "clamp"}));
    cmd->add_option("--scale", o->scale, "Height scale s in uv units (default 0.05)")
        ->check(inRange(0.0, 100.0));
    addDistanceOption(*cmd, "--distance", o->distance,
                      "How far a blocker may be, uv units, or inf (default 0.1: Material Maker's "
                      "radius; the peers' radii follow it)");
    cmd->add_option("--reference-directions", o->referenceDirections,
                    "Azimuths of the exact value the others are measured against (default 1024)")
        ->check(inRange(1, 4096));
    std::vector<std::string> methods(occlusionMethodNames().begin(), occlusionMethodNames().end());
    cmd->add_option("--methods", o->methods, "Only these methods (default: every one)")
        ->delimiter(',')
        ->check(CLI::IsMember(methods));
    cmd->add_option("--repeats", o->repeats, "Timed runs per method and map, fastest reported")
        ->check(inRange(1, 100));
    cmd->add_option("--out", o->out, "Output CSV; - for standard output");
    cmd->add_option("--plot", o->plot, "Error-against-time plot (.svg)");
    cmd->add_flag("--quiet", o->quiet, "No progress line and no summary table");
    return [o] { return runBenchAo(*o); };
}

} // namespace px::cli

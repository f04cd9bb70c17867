#include "parallax/eval/OcclusionBench.h"

#include "parallax/bake/OcclusionBaker.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace px {

namespace {

constexpr std::array<std::string_view, 5> kMethodNames{"exact", "hbao", "max-of-sine", "ssao-sum",
                                                       "ray-march"};

using Bake =
    std::function<Result<Image>(const HeightField&, const PeerSurfaceOptions&, const BakeControl&)>;

OcclusionMethod exactMethod(int directions, double distance) {
    return {"exact", std::to_string(directions) + " directions", static_cast<double>(directions),
            [directions, distance](const HeightField& field, const PeerSurfaceOptions& surface,
                                   const BakeControl& control) -> Result<Image> {
                OcclusionBakeOptions options;
                options.heightScale = surface.heightScale;
                options.wrap = surface.wrap;
                options.distance = distance;
                options.directions = directions;
                Result<OcclusionMaps> maps =
                    bakeOcclusion(field, options, OcclusionOutputs::AmbientOcclusion, control);
                if (!maps)
                    return maps.error();
                return std::move(maps->occlusion);
            }};
}

// "8x4": counts as the table names them.
std::string times(int a, int b) {
    return std::to_string(a) + "x" + std::to_string(b);
}

} // namespace

std::span<const std::string_view> occlusionMethodNames() {
    return kMethodNames;
}

std::vector<OcclusionMethod> defaultOcclusionMethods(double distance) {
    std::vector<OcclusionMethod> methods;
    for (int directions : {4, 8, 16, 32, 64, 128})
        methods.push_back(exactMethod(directions, distance));
    const double radius = std::isfinite(distance) ? distance : 0.1;
    const auto hbao = [&](int directions, int steps, const std::string& who) {
        HbaoOptions o;
        o.directions = directions;
        o.steps = steps;
        o.radius = radius;
        methods.push_back({"hbao", times(directions, steps) + ", " + who,
                           static_cast<double>(directions) * steps,
                           [o](const HeightField& f, const PeerSurfaceOptions& s,
                               const BakeControl& c) { return hbaoOcclusion(f, s, o, c); }});
    };
    hbao(8, 4, "Material Maker");
    for (int quality : {4, 8, 16})
        hbao(quality, quality, "Substance quality " + std::to_string(quality));
    {
        const MaxOfSineOptions o;
        methods.push_back({"max-of-sine", times(o.directions, o.steps) + ", Materialize",
                           static_cast<double>(o.directions) * o.steps,
                           [o](const HeightField& f, const PeerSurfaceOptions& s,
                               const BakeControl& c) { return maxOfSineOcclusion(f, s, o, c); }});
    }
    for (int n : {2, 4, 8}) {
        const int side = 2 * n + 1;
        methods.push_back(
            {"ssao-sum", times(side, side) + " grid", static_cast<double>(side * side - 1),
             [n, distance](const HeightField& f, const PeerSurfaceOptions& s,
                           const BakeControl& c) {
                 SsaoSumOptions o;
                 o.radius = n;
                 // The grid spans the distance, as an artist sets its radius.
                 o.spacingTexels =
                     std::isfinite(distance) ? distance * std::max(f.width, f.height) / n : 1.0;
                 return ssaoSumOcclusion(f, s, o, c);
             }});
    }
    for (int rays : {16, 64, 256}) {
        RayMarchOptions o;
        o.rays = rays;
        o.distance = distance;
        methods.push_back({"ray-march", std::to_string(rays) + " rays", static_cast<double>(rays),
                           [o](const HeightField& f, const PeerSurfaceOptions& s,
                               const BakeControl& c) { return rayMarchOcclusion(f, s, o, c); }});
    }
    return methods;
}

double nearestRankQuantile(std::vector<double>& values, double p) {
    if (values.empty())
        return 0.0;
    const auto n = static_cast<double>(values.size());
    const auto rank = static_cast<std::size_t>(std::clamp(std::ceil(p * n), 1.0, n)) - 1;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                     values.end());
    return values[rank];
}

namespace {

// The statistics of a set of errors (already in 8-bit steps).
void fillStats(OcclusionBenchRow& row, std::vector<double>& errors) {
    double sum = 0.0, worst = 0.0;
    for (double e : errors) {
        sum += e;
        worst = std::max(worst, e);
    }
    row.texels = static_cast<std::int64_t>(errors.size());
    row.meanSteps = errors.empty() ? 0.0 : sum / static_cast<double>(errors.size());
    row.maxSteps = worst;
    row.p999Steps = nearestRankQuantile(errors, 0.999);
}

} // namespace

Result<OcclusionBenchReport> runOcclusionBench(const OcclusionBenchConfig& config,
                                               const EvalControl& control) {
    if (config.maps.empty())
        return Error{"give at least one height map"};
    if (config.referenceDirections < 1 || config.referenceDirections > kMaxOcclusionDirections)
        return Error{"the reference needs 1 to " + std::to_string(kMaxOcclusionDirections) +
                     " directions"};
    if (config.repeats < 1)
        return Error{"give at least one timed run per method"};
    const std::vector<OcclusionMethod> methods =
        config.methods.empty() ? defaultOcclusionMethods(config.distance) : config.methods;
    const PeerSurfaceOptions surface{config.heightScale, config.wrap};
    BakeControl bake;
    bake.cancel = control.cancel;

    OcclusionBenchReport report;
    report.heightScale = config.heightScale;
    report.wrap = config.wrap;
    report.distance = config.distance;
    report.referenceDirections = config.referenceDirections;
    std::vector<std::vector<double>> pooledErrors(methods.size());
    std::vector<double> pooledSeconds(methods.size(), 0.0);
    const int total = static_cast<int>(config.maps.size() * (methods.size() + 1));
    int done = 0;
    for (const OcclusionBenchMap& map : config.maps) {
        const HeightField& field = *map.field;
        Result<Image> exact =
            exactMethod(config.referenceDirections, config.distance).bake(field, surface, bake);
        if (!exact)
            return exact.error().cancelled() ? evaluationCancelled()
                                             : exact.error().prefixed(map.name + ": ");
        if (control.progress)
            control.progress({++done, total, "exact reference, " + map.name});
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const OcclusionMethod& method = methods[m];
            double fastest = INFINITY;
            Result<Image> ao = Image{};
            for (int run = 0; run < config.repeats; ++run) {
                const auto start = std::chrono::steady_clock::now();
                ao = method.bake(field, surface, bake);
                const double seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (!ao)
                    return ao.error().cancelled()
                               ? evaluationCancelled()
                               : ao.error().prefixed(map.name + ", " + method.method + " " +
                                                     method.setting + ": ");
                fastest = std::min(fastest, seconds);
            }
            std::vector<double> errors(exact->pixels.size());
            for (std::size_t i = 0; i < errors.size(); ++i)
                errors[i] = std::abs(double(ao->pixels[i]) - double(exact->pixels[i])) * 255.0;
            pooledErrors[m].insert(pooledErrors[m].end(), errors.begin(), errors.end());
            pooledSeconds[m] += fastest;
            OcclusionBenchRow row{map.name,      field.width,    field.height,
                                  method.method, method.setting, method.samples};
            row.seconds = fastest;
            fillStats(row, errors);
            report.rows.push_back(std::move(row));
            if (control.progress)
                control.progress(
                    {++done, total, method.method + " " + method.setting + ", " + map.name});
        }
    }
    for (std::size_t m = 0; m < methods.size(); ++m) {
        OcclusionBenchRow row{
            "all", 0, 0, methods[m].method, methods[m].setting, methods[m].samples};
        row.seconds = pooledSeconds[m];
        fillStats(row, pooledErrors[m]);
        report.pooled.push_back(std::move(row));
    }
    return report;
}

namespace {

// A CSV field: quoted when it holds a comma or a quote.
std::string field(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
    std::string quoted = "\"";
    for (char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

} // namespace

std::string occlusionBenchCsv(const OcclusionBenchReport& report) {
    std::ostringstream out;
    out << kOcclusionBenchCsvHeader << "\n";
    char numbers[256];
    const auto line = [&](const OcclusionBenchRow& r) {
        out << field(r.map) << "," << r.width << "," << r.height << "," << r.texels << ","
            << toString(report.wrap) << ",";
        std::snprintf(numbers, sizeof numbers, "%g,%g,%d,", report.heightScale, report.distance,
                      report.referenceDirections);
        out << numbers << field(r.method) << "," << field(r.setting) << ",";
        std::snprintf(numbers, sizeof numbers, "%g,%.4f,%.4f,%.4f,%.6f,%.1f", r.samples,
                      r.meanSteps, r.p999Steps, r.maxSteps, r.seconds, r.nsPerTexel());
        out << numbers << "\n";
    };
    for (const OcclusionBenchRow& r : report.rows)
        line(r);
    for (const OcclusionBenchRow& r : report.pooled)
        line(r);
    return out.str();
}

} // namespace px

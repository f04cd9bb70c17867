#pragma once
// Error against cost for ambient occlusion: the exact baker at several azimuth counts and the
// peers' methods (PeerOcclusion.h), each measured against the exact baker at many azimuths on the
// same maps — mean, p99.9 and max of |AO - exact| in 8-bit steps (x 255), and the wall time of the
// whole bake on every core (fastest of the repeats). The table and plot of docs/bakers.md.

#include "parallax/Result.h"
#include "parallax/eval/EvalControl.h"
#include "parallax/eval/PeerOcclusion.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace px {

// One method at one setting: `method` is "exact", "hbao", "max-of-sine", "ssao-sum" or
// "ray-march"; `setting` says its counts ("64 directions", "8x4, Material Maker").
struct OcclusionMethod {
    std::string method;
    std::string setting;
    double samples = 0.0; // height samples per texel it takes (for the exact baker: azimuths)
    std::function<Result<Image>(const HeightField&, const PeerSurfaceOptions&, const BakeControl&)>
        bake;
};

std::span<const std::string_view> occlusionMethodNames();

// The table's rows: the exact baker at 4 to 128 azimuths, HBAO as Material Maker (8x4, bias 15°)
// and as Substance's quality 4, 8, 16 (that many directions and steps), Materialize's max of sine
// (99 x 50 out to 50 texels), the SSAO sum with N = 2, 4, 8 spanning `distance` (1 texel apart
// when unlimited), and the ray cast with 16, 64, 256 rays. Radii are `distance` (0.1 uv, Material
// Maker's, when unlimited).
std::vector<OcclusionMethod> defaultOcclusionMethods(double distance);

struct OcclusionBenchMap {
    std::string name;
    std::shared_ptr<const HeightField> field;
};

struct OcclusionBenchConfig {
    std::vector<OcclusionBenchMap> maps;
    std::vector<OcclusionMethod> methods; // empty: defaultOcclusionMethods(distance)
    float heightScale = 0.05f;
    WrapMode wrap = WrapMode::Repeat;
    double distance = 0.1;          // the exact value's D; +inf: unlimited
    int referenceDirections = 1024; // the exact value
    int repeats = 1;                // timed runs per method and map, fastest kept
};

struct OcclusionBenchRow {
    std::string map; // "all" for the rows pooled over every map
    int width = 0;   // the map's size (0 when pooled)
    int height = 0;
    std::string method;
    std::string setting;
    double samples = 0.0;
    std::int64_t texels = 0;
    double meanSteps = 0.0; // |AO - exact| x 255
    double p999Steps = 0.0;
    double maxSteps = 0.0;
    double seconds = 0.0; // wall time of the bake, every core (pooled: the sum)
    double nsPerTexel() const { return texels > 0 ? seconds * 1e9 / texels : 0.0; }
};

struct OcclusionBenchReport {
    float heightScale = 0.05f;
    WrapMode wrap = WrapMode::Repeat;
    double distance = 0.1;
    int referenceDirections = 1024;
    std::vector<OcclusionBenchRow> rows;   // per map, the methods' order
    std::vector<OcclusionBenchRow> pooled; // per method, every texel of every map
};

// Errors: no maps or a bad setting (as the bakers say), a method's own error, cancellation
// (evaluationCancelled()). Progress: one unit per map and method.
Result<OcclusionBenchReport> runOcclusionBench(const OcclusionBenchConfig& config,
                                               const EvalControl& control = {});

inline constexpr std::string_view kOcclusionBenchCsvHeader =
    "map,width,height,texels,wrap,scale,distance,reference_directions,method,setting,samples,"
    "mean_error_8bit,p999_error_8bit,max_error_8bit,seconds,ns_per_texel";

// Rows per map, then the pooled rows (map "all").
std::string occlusionBenchCsv(const OcclusionBenchReport& report);

// The p-quantile (0..1) of `values` by the nearest rank (ceil(p n)-th smallest); 0 when empty.
// Reorders `values`.
double nearestRankQuantile(std::vector<double>& values, double p);

} // namespace px

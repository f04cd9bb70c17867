#pragma once
// The bench report as CSV (columns documented in the README, "Benchmark and stability"): one row
// per polar angle, setting, map and scale, then one pooled row (map "all") per angle and setting.

#include "parallax/eval/Bench.h"

#include <string>
#include <string_view>

namespace px {

inline constexpr std::string_view kBenchCsvHeader =
    "map,width,height,wrap,scale,polar,azimuth,rays,technique,setting,default,"
    "min_layers,max_layers,binary_steps,secant_steps,max_steps,"
    "mean_error,p99_error,max_error,wrong_surface,invalid,"
    "mean_fetches,p99_fetches,max_fetches,cpu_ns_per_ray,gpu_ms_per_frame,gpu_renderer,"
    "gpu_kernels,gpu_mean_error,gpu_p99_error,gpu_max_error,gpu_mean_fetches";
// The header before the GPU kernels' errors were reported (read, never written).
inline constexpr std::string_view kBenchCsvHeaderV1 =
    "map,width,height,wrap,scale,polar,azimuth,rays,technique,setting,default,"
    "min_layers,max_layers,binary_steps,secant_steps,max_steps,"
    "mean_error,p99_error,max_error,wrong_surface,invalid,"
    "mean_fetches,p99_fetches,max_fetches,cpu_ns_per_ray,gpu_ms_per_frame,gpu_renderer";

std::string benchCsv(const BenchReport& report);

// Reads a report benchCsv() wrote (to plot it again, or to compare runs); `source` names it in
// errors: another header, a short line, a value that is not a number, no rows.
Result<BenchReport> parseBenchCsv(std::string_view text, const std::string& source);

} // namespace px

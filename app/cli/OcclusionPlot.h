#pragma once
// Draws the occlusion bench (parallax/eval/OcclusionBench.h) to an SVG with PLplot, as the
// technique bench's work-precision plot is drawn: error in 8-bit steps against time per texel,
// one series per method over its settings, pooled over every map.

#include "parallax/Result.h"
#include "parallax/eval/OcclusionBench.h"

#include <string>

namespace px::cli {

// Writes atomically; errors name the file (an extension other than .svg, an unwritable folder).
Status writeOcclusionPlot(const std::string& path, const OcclusionBenchReport& report,
                          const std::string& title, const std::string& subtitle);

} // namespace px::cli

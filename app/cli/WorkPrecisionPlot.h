#pragma once
// Draws a work-precision chart (core/include/parallax/eval/WorkPrecision.h) to an SVG file.

#include "parallax/Result.h"
#include "parallax/eval/WorkPrecision.h"

#include <string>

namespace px::cli {

struct PlotLabels {
    std::string title;
    std::string subtitle; // the machine and renderer the times come from
};

// Writes atomically; errors name the file (an extension other than .svg, an unwritable folder).
Status writeWorkPrecisionPlot(const std::string& path, const WorkPrecisionChart& chart,
                              const PlotLabels& labels);

} // namespace px::cli

// The occlusion bench's SVG: two panels (mean and p99.9 error, 8-bit steps, against nanoseconds
// per texel), log axes, one coloured series per method. PLplot for the reasons
// WorkPrecisionPlot.cpp gives; the file is finished the same way (PLplot cannot report a full
// disk).

#include "OcclusionPlot.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/OutputGate.h"
#include "parallax/io/Temporaries.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <plplot.h>
#include <vector>

namespace px::cli {
namespace {

constexpr PLFLT kCharacterMm = 2.6;
// Errors below this many 8-bit steps are drawn on it (a log axis has no 0).
constexpr double kFloorSteps = 0.01;

enum Slot { kBackground = 0, kInk = 1, kGrid = 2, kTarget = 3, kFirstMethod = 4 };
constexpr std::array<std::array<int, 3>, 5> kPalette{
    {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40}, {148, 103, 189}}};
constexpr std::array<const char*, 5> kSymbols{"●", "■", "▲", "◆", "▼"};

int methodIndex(const std::string& method) {
    const auto names = occlusionMethodNames();
    const auto it = std::find(names.begin(), names.end(), method);
    return it == names.end() ? 0 : static_cast<int>(it - names.begin()) % 5;
}

struct Range {
    int lo = 0, hi = 1; // decades
};

Range decades(const std::vector<double>& values) {
    double lo = INFINITY, hi = -INFINITY;
    for (double v : values) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (!(lo <= hi))
        return {};
    Range r{static_cast<int>(std::floor(std::log10(lo))),
            static_cast<int>(std::ceil(std::log10(hi)))};
    if (r.hi <= r.lo)
        r.hi = r.lo + 1;
    return r;
}

void drawPanel(const OcclusionBenchReport& report, bool p999) {
    std::vector<double> costs, errors{kFloorSteps, 2.0};
    for (const OcclusionBenchRow& r : report.pooled) {
        costs.push_back(std::max(r.nsPerTexel(), 1e-3));
        errors.push_back(std::max(p999 ? r.maxSteps : r.meanSteps, kFloorSteps));
    }
    const Range x = decades(costs), y = decades(errors);
    plwind(x.lo, x.hi, y.lo, y.hi);
    plcol0(kGrid);
    plbox("ghst", 0.0, 0, "ghst", 0.0, 0);
    // The targets of the exact bake: 0.5 steps mean, 2 steps at p99.9.
    const PLFLT target = std::log10(p999 ? 2.0 : 0.5);
    const PLFLT tx[2] = {double(x.lo), double(x.hi)}, ty[2] = {target, target};
    plcol0(kTarget);
    pllsty(2);
    plline(2, tx, ty);
    pllsty(1);
    plschr(0.0, 0.8);
    for (const std::string_view name : occlusionMethodNames()) {
        std::vector<PLFLT> xs, ys, top;
        for (const OcclusionBenchRow& r : report.pooled) {
            if (r.method != name)
                continue;
            xs.push_back(std::log10(std::max(r.nsPerTexel(), 1e-3)));
            ys.push_back(std::log10(std::max(p999 ? r.p999Steps : r.meanSteps, kFloorSteps)));
            top.push_back(std::log10(std::max(r.maxSteps, kFloorSteps)));
        }
        if (xs.empty())
            continue;
        const int i = methodIndex(std::string(name));
        plcol0(kFirstMethod + i);
        plwidth(1.5);
        if (xs.size() > 1)
            plline(static_cast<PLINT>(xs.size()), xs.data(), ys.data());
        plwidth(1.0);
        plstring(static_cast<PLINT>(xs.size()), xs.data(), ys.data(), kSymbols[i]);
        if (p999) { // dotted up to the worst texel
            pllsty(3);
            for (std::size_t k = 0; k < xs.size(); ++k) {
                const PLFLT wx[2] = {xs[k], xs[k]}, wy[2] = {ys[k], top[k]};
                plline(2, wx, wy);
            }
            pllsty(1);
        }
    }
    plschr(0.0, 1.0);
    plcol0(kInk);
    plbox("bcnstl", 0.0, 0, "bcnstlv", 0.0, 0);
    pllab("ns per texel (all cores)",
          p999 ? "p99.9 error, 8-bit steps; dotted: up to max" : "mean error, 8-bit steps",
          p999 ? "p99.9 (dashed: 2 steps)" : "mean (dashed: 0.5 steps)");
}

void drawLegend() {
    const auto names = occlusionMethodNames();
    std::vector<const char*> text, symbols;
    std::vector<PLINT> options, colours, lineStyles, counts, textColours;
    std::vector<PLFLT> widths, scales;
    for (std::size_t i = 0; i < names.size(); ++i) {
        text.push_back(names[i].data()); // the table's names are NUL-terminated literals
        symbols.push_back(kSymbols[i]);
        options.push_back(PL_LEGEND_LINE | PL_LEGEND_SYMBOL);
        colours.push_back(kFirstMethod + static_cast<PLINT>(i));
        lineStyles.push_back(1);
        counts.push_back(1);
        textColours.push_back(kInk);
        widths.push_back(1.5);
        scales.push_back(0.8);
    }
    PLFLT width = 0.0, height = 0.0;
    plschr(0.0, 0.8);
    const auto n = static_cast<PLINT>(names.size());
    pllegend(&width, &height, PL_LEGEND_BACKGROUND | PL_LEGEND_ROW_MAJOR,
             PL_POSITION_BOTTOM | PL_POSITION_INSIDE, 0.0, 0.04, 0.03, kBackground, kGrid, 1, 1, n,
             n, options.data(), 1.0, 1.0, 1.8, 0.0, textColours.data(), text.data(), nullptr,
             nullptr, nullptr, nullptr, colours.data(), lineStyles.data(), widths.data(),
             colours.data(), scales.data(), counts.data(), symbols.data());
    plschr(0.0, 1.0);
}

} // namespace

Status writeOcclusionPlot(const std::string& path, const OcclusionBenchReport& report,
                          const std::string& title, const std::string& subtitle) {
    if (std::filesystem::path(path).extension() != ".svg")
        return fileError(path, "the plot is written as SVG: name it .svg");
    const std::filesystem::path temp = temporaryPathFor(path);
    const TemporaryGuard guard(temp);
    // PLplot ends the process when it cannot open its file: make sure it can first.
    if (!std::ofstream(temp))
        return fileError(path, "cannot create the file (missing folder or no permission)");
    const int panelWidth = 560, panelHeight = 420, header = 110;
    plsdev("svg");
    plsfnam(temp.c_str());
    plspage(0.0, 0.0, 2 * panelWidth, panelHeight + header, 0, 0);
    plscmap0n(kFirstMethod + static_cast<int>(kPalette.size()));
    plscol0(kBackground, 255, 255, 255);
    plscol0(kInk, 0, 0, 0);
    plscol0(kGrid, 225, 225, 225);
    plscol0(kTarget, 120, 120, 120);
    for (std::size_t i = 0; i < kPalette.size(); ++i)
        plscol0(kFirstMethod + static_cast<int>(i), kPalette[i][0], kPalette[i][1], kPalette[i][2]);
    plinit();
    pladv(0);
    plschr(kCharacterMm, 1.0);
    const double headerFraction = static_cast<double>(header) / (panelHeight + header);
    plvpor(0.0, 1.0, 1.0 - headerFraction, 1.0);
    plcol0(kInk);
    plschr(0.0, 1.3);
    plmtex("t", -1.6, 0.5, 0.5, title.c_str());
    plschr(0.0, 0.9);
    plmtex("t", -3.6, 0.5, 0.5, subtitle.c_str());
    plschr(0.0, 1.0);
    plwind(0.0, 1.0, 0.0, 1.0);
    drawLegend();
    for (int c = 0; c < 2; ++c) {
        const double x0 = c * 0.5, cellH = 1.0 - headerFraction;
        plvpor(x0 + 0.06, x0 + 0.48, 0.16 * cellH, 0.91 * cellH);
        drawPanel(report, c == 1);
    }
    plend();

    // A complete SVG ends with its closing tag; the checked writer then writes it for good.
    Result<std::string> svg = readTextFile(temp.string(), false); // our own file, not an input
    const bool complete =
        svg && svg->find("</svg>", svg->size() > 64 ? svg->size() - 64 : 0) != std::string::npos;
    discardTemporary(temp);
    if (!complete)
        return fileError(path, "writing failed (the plotting library stopped early); the "
                               "previous file, if any, is unchanged");
    return writeFileAtomically(path, *svg);
}

} // namespace px::cli

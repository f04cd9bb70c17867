// The work-precision SVG, drawn with PLplot (Debian libplplot-dev). Why PLplot: a maintained C
// plotting library with real log axes, legends and an SVG driver built into the core library, it
// needs no display and keeps parallax-cli free of Qt (the CLI links the core and the renderer
// only). The editor draws the same WorkPrecisionChart with QPainter, interactively; this file only
// renders it, so the data and the picture cannot disagree.

#include "WorkPrecisionPlot.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/OutputGate.h"
#include "parallax/io/Temporaries.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <plplot.h>
#include <unistd.h>
#include <vector>

namespace px::cli {
namespace {

// Character height: PLplot's default scales with the page and is far too large for a grid.
constexpr PLFLT kCharacterMm = 2.6;

constexpr PLFLT kPadDecades = 0.06;

// Colour map 0 slots: background, ink, front, grid, then one per technique.
enum Slot { kBackground = 0, kInk = 1, kFront = 2, kGrid = 3, kFirstTechnique = 4 };

// Tableau 10: distinguishable, also in grey print.
constexpr std::array<std::array<int, 3>, 10> kPalette{{{31, 119, 180},
                                                       {255, 127, 14},
                                                       {44, 160, 44},
                                                       {214, 39, 40},
                                                       {148, 103, 189},
                                                       {140, 86, 75},
                                                       {227, 119, 194},
                                                       {127, 127, 127},
                                                       {188, 189, 34},
                                                       {23, 190, 207}}};
constexpr std::array<const char*, 10> kSymbols{"●", "■", "▲", "◆", "▼", "★", "✚", "▶", "✖", "◀"};

int techniqueSlot(Technique t) {
    return kFirstTechnique + static_cast<int>(t) % static_cast<int>(kPalette.size());
}
const char* techniqueSymbol(Technique t) {
    return kSymbols[static_cast<std::size_t>(t) % kSymbols.size()];
}

void setPalette() {
    plscmap0n(kFirstTechnique + static_cast<int>(kPalette.size()));
    plscol0(kBackground, 255, 255, 255);
    plscol0(kInk, 0, 0, 0);
    plscol0(kFront, 200, 200, 200);
    plscol0(kGrid, 225, 225, 225);
    for (std::size_t i = 0; i < kPalette.size(); ++i)
        plscol0(kFirstTechnique + static_cast<int>(i), kPalette[i][0], kPalette[i][1],
                kPalette[i][2]);
}

std::string formatDegrees(double degrees) {
    char text[32];
    std::snprintf(text, sizeof text, "%g°", degrees);
    return text;
}

// The front as a staircase: from each front point across to the next one's cost, then down.
void drawFront(const WorkPrecisionPanel& panel) {
    std::vector<PLFLT> x, y;
    for (std::size_t k = 0; k < panel.front.size(); ++k) {
        const WorkPrecisionPoint& p = panel.at(panel.front[k]);
        if (k > 0) {
            x.push_back(std::log10(p.cost));
            y.push_back(y.back());
        }
        x.push_back(std::log10(p.cost));
        y.push_back(std::log10(p.plotError));
    }
    if (x.empty())
        return;
    x.push_back(panel.costRange.hiExp + kPadDecades);
    y.push_back(y.back());
    plcol0(kFront);
    plwidth(7.0);
    plline(static_cast<PLINT>(x.size()), x.data(), y.data());
    plwidth(1.0);
}

void drawPanel(const WorkPrecisionChart& chart, const WorkPrecisionPanel& panel) {
    // A little room beyond the decades, so points on a decade are not drawn on the frame.
    plwind(panel.costRange.loExp - kPadDecades, panel.costRange.hiExp + kPadDecades,
           panel.errorRange.loExp, panel.errorRange.hiExp + kPadDecades);
    plcol0(kGrid);
    plbox("ghst", 0.0, 0, "ghst", 0.0, 0);
    // The floor: errors at or below it are the reference's own rounding.
    const PLFLT floorY = std::log10(chart.errorFloor);
    plcol0(kInk);
    pllsty(2);
    const PLFLT fx[2] = {panel.costRange.loExp - kPadDecades, panel.costRange.hiExp + kPadDecades};
    const PLFLT fy[2] = {floorY, floorY};
    plline(2, fx, fy);
    pllsty(1);
    drawFront(panel);

    plschr(0.0, 0.8);
    for (const WorkPrecisionSeries& series : panel.series) {
        std::vector<PLFLT> x, y;
        for (const WorkPrecisionPoint& p : series.points) {
            x.push_back(std::log10(p.cost));
            y.push_back(std::log10(p.plotError));
        }
        plcol0(techniqueSlot(series.technique));
        plwidth(1.5);
        if (x.size() > 1)
            plline(static_cast<PLINT>(x.size()), x.data(), y.data());
        plwidth(1.0);
        plstring(static_cast<PLINT>(x.size()), x.data(), y.data(),
                 techniqueSymbol(series.technique));
        // The tail p99 hides: a dotted whisker up to the worst ray, and how many rays found
        // another surface.
        pllsty(3);
        for (const WorkPrecisionPoint& p : series.points) {
            if (p.plotMaxError <= p.plotError)
                continue;
            const PLFLT wx[2] = {std::log10(p.cost), std::log10(p.cost)};
            const PLFLT wy[2] = {std::log10(p.plotError), std::log10(p.plotMaxError)};
            plline(2, wx, wy);
            if (p.wrongSurface > 0) {
                const std::string label = " " + std::to_string(p.wrongSurface) + " wrong";
                plptex(wx[1], wy[1], 1.0, 0.0, 0.0, label.c_str());
            }
        }
        pllsty(1);
        for (const WorkPrecisionPoint& p : series.points) {
            if (!p.setting.isDefault)
                continue;
            const PLFLT dx = std::log10(p.cost), dy = std::log10(p.plotError);
            plschr(0.0, 1.9);
            plstring(1, &dx, &dy, "○");
            plschr(0.0, 0.8);
        }
    }
    plschr(0.0, 1.0);
    plcol0(kInk);
    plbox("bcnstl", 0.0, 0, "bcnstlv", 0.0, 0);
    char title[96];
    std::snprintf(title, sizeof title, "polar %s", formatDegrees(panel.polarDeg).c_str());
    pllab(std::string(costAxisTitle(panel.axis)).c_str(),
          "p99 hit error (texels); dotted: up to max", title);
}

// One legend for every panel, in the header band: every technique present, then the marks.
void drawLegend(const WorkPrecisionChart& chart) {
    std::vector<Technique> techniques;
    for (const WorkPrecisionPanel& panel : chart.panels) {
        for (const WorkPrecisionSeries& series : panel.series) {
            if (std::find(techniques.begin(), techniques.end(), series.technique) ==
                techniques.end())
                techniques.push_back(series.technique);
        }
    }
    std::sort(techniques.begin(), techniques.end());
    std::vector<std::string> names;
    std::vector<PLINT> options, colours, lineStyles;
    std::vector<PLFLT> lineWidths, symbolScales;
    std::vector<PLINT> symbolCounts;
    std::vector<std::string> symbols;
    for (Technique t : techniques) {
        names.emplace_back(info(t).name);
        options.push_back(PL_LEGEND_LINE | PL_LEGEND_SYMBOL);
        colours.push_back(techniqueSlot(t));
        lineWidths.push_back(1.5);
        symbols.emplace_back(techniqueSymbol(t));
        symbolScales.push_back(0.8);
    }
    names.emplace_back("Pareto front");
    options.push_back(PL_LEGEND_LINE);
    colours.push_back(kFront);
    lineWidths.push_back(7.0);
    symbols.emplace_back("");
    symbolScales.push_back(0.8);
    names.emplace_back("default setting");
    options.push_back(PL_LEGEND_SYMBOL);
    colours.push_back(kInk);
    lineWidths.push_back(1.0);
    symbols.emplace_back("○");
    symbolScales.push_back(1.9);
    names.emplace_back("error floor (exact)");
    options.push_back(PL_LEGEND_LINE);
    colours.push_back(kInk);
    lineWidths.push_back(1.0);
    symbols.emplace_back("");
    symbolScales.push_back(0.8);

    const auto n = static_cast<PLINT>(names.size());
    lineStyles.assign(names.size(), 1);
    lineStyles.back() = 2;
    symbolCounts.assign(names.size(), 1);
    std::vector<const char*> text, symbolText;
    for (std::size_t i = 0; i < names.size(); ++i) {
        text.push_back(names[i].c_str());
        symbolText.push_back(symbols[i].c_str());
    }
    std::vector<PLINT> textColours(names.size(), kInk);
    PLFLT width = 0.0, height = 0.0;
    plschr(0.0, 0.8);
    const PLINT rows = 2, columns = (n + 1) / 2;
    pllegend(&width, &height, PL_LEGEND_BACKGROUND | PL_LEGEND_ROW_MAJOR,
             PL_POSITION_BOTTOM | PL_POSITION_INSIDE, 0.0, 0.04, 0.03, kBackground, kGrid, 1, rows,
             columns, n, options.data(), 1.0, 1.0, 1.8, 0.0, textColours.data(), text.data(),
             nullptr, nullptr, nullptr, nullptr, colours.data(), lineStyles.data(),
             lineWidths.data(), colours.data(), symbolScales.data(), symbolCounts.data(),
             symbolText.data());
    plschr(0.0, 1.0);
}

// Why PLplot's file came out incomplete: the system's answer to one more checked byte.
std::string whyUnwritable(const std::filesystem::path& file) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd < 0)
        return systemReason(errno);
    const char byte = '\n';
    int code = ::write(fd, &byte, 1) == 1 && ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    return code != 0 ? systemReason(code) : std::string("the plotting library stopped early");
}

} // namespace

Status writeWorkPrecisionPlot(const std::string& path, const WorkPrecisionChart& chart,
                              const PlotLabels& labels) {
    if (std::filesystem::path(path).extension() != ".svg")
        return fileError(path, "the plot is written as SVG: name it .svg");
    const std::filesystem::path temp = temporaryPathFor(path);
    const TemporaryGuard guard(temp);
    // PLplot ends the process when it cannot open its file: make sure it can first.
    if (!std::ofstream(temp))
        return fileError(path, "cannot create the file (missing folder or no permission)");
    const int columns = static_cast<int>(chart.axes.size());
    const int rows = static_cast<int>(chart.polarDeg.size());
    const int panelWidth = 560, panelHeight = 400, header = 120;
    const int width = panelWidth * columns, height = panelHeight * rows + header;

    plsdev("svg");
    plsfnam(temp.c_str());
    plspage(0.0, 0.0, width, height, 0, 0);
    setPalette();
    plinit();
    pladv(0);
    plschr(kCharacterMm, 1.0);
    // Panels in a grid below a header band, each with room for its axis labels.
    const double headerFraction = static_cast<double>(header) / height;
    plvpor(0.0, 1.0, 1.0 - headerFraction, 1.0);
    plcol0(kInk);
    plschr(0.0, 1.3);
    plmtex("t", -1.6, 0.5, 0.5, labels.title.c_str());
    plschr(0.0, 0.9);
    plmtex("t", -3.6, 0.5, 0.5, labels.subtitle.c_str());
    plschr(0.0, 1.0);
    plwind(0.0, 1.0, 0.0, 1.0);
    drawLegend(chart);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const double x0 = static_cast<double>(c) / columns;
            const double y1 = (1.0 - headerFraction) * (1.0 - static_cast<double>(r) / rows);
            const double cellW = 1.0 / columns, cellH = (1.0 - headerFraction) / rows;
            plvpor(x0 + 0.12 * cellW, x0 + 0.96 * cellW, y1 - 0.84 * cellH, y1 - 0.09 * cellH);
            drawPanel(chart, chart.panel(r, c));
        }
    }
    plend();

    // PLplot does not report a full disk: a complete SVG ends with its closing tag. The checked
    // writer then writes it for good (every step checked, as every other output).
    Result<std::string> svg = readTextFile(temp.string(), false); // our own file, not an input
    const std::string end = "</svg>";
    const bool complete =
        svg && svg->find(end, svg->size() > 64 ? svg->size() - 64 : 0) != std::string::npos;
    const std::string reason = complete ? std::string() : whyUnwritable(temp);
    discardTemporary(temp);
    if (!complete)
        return fileError(path, "writing failed (" + reason +
                                   "); the previous file, if any, is unchanged");
    return writeFileAtomically(path, *svg);
}

} // namespace px::cli

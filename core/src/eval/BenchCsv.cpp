#include "parallax/eval/BenchCsv.h"

#include <charconv>
#include <cstdio>

namespace px {
namespace {

std::string number(const char* format, double value) {
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// The shortest text that reads back as the same value: 0.05 rather than 0.0500000007.
template <typename T> std::string shortest(T value) {
    char text[48];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    return ec == std::errc() ? std::string(text, end) : std::string();
}

// RFC 4180: quote a field holding a comma, quote or line break; double its quotes.
std::string field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos)
        return text;
    std::string quoted = "\"";
    for (char c : text) {
        quoted += c;
        if (c == '"')
            quoted += '"';
    }
    return quoted + "\"";
}

void appendRow(std::string& csv, const BenchReport& report, const BenchRow& row) {
    const TechniqueInfo& ti = info(row.setting.technique);
    const TraceParams& p = row.setting.params;
    auto param = [](bool used, int value) { return used ? std::to_string(value) : std::string(); };
    const std::string cells[] = {
        field(row.map),
        row.pooled ? "" : std::to_string(row.width),
        row.pooled ? "" : std::to_string(row.height),
        std::string(toString(report.wrap)),
        row.scale ? shortest(*row.scale) : "",
        shortest(row.polarDeg),
        shortest(report.azimuthDeg),
        std::to_string(report.rays),
        std::string(ti.name),
        field(row.setting.label),
        row.setting.isDefault ? "1" : "0",
        param(ti.usesLayers, p.minLayers),
        param(ti.usesLayers, p.maxLayers),
        param(ti.usesBinarySteps, p.binarySteps),
        param(ti.usesSecantSteps, p.secantSteps),
        param(ti.usesMaxSteps, p.maxSteps),
        number("%.9g", row.stats.meanError),
        number("%.9g", row.stats.p99Error),
        number("%.9g", row.stats.maxError),
        std::to_string(row.stats.wrongSurface),
        std::to_string(row.stats.invalid),
        number("%.9g", row.stats.meanFetches),
        number("%.9g", row.stats.p99Fetches),
        std::to_string(row.stats.maxFetches),
        row.cpuNsPerRay ? number("%.1f", *row.cpuNsPerRay) : "",
        row.gpuMsPerFrame ? number("%.3f", *row.gpuMsPerFrame) : "",
        field(row.gpuRenderer),
    };
    bool first = true;
    for (const std::string& cell : cells) {
        if (!first)
            csv += ',';
        csv += cell;
        first = false;
    }
    csv += '\n';
}

} // namespace

std::string benchCsv(const BenchReport& report) {
    std::string csv(kBenchCsvHeader);
    csv += '\n';
    for (const BenchRow& row : report.rows)
        appendRow(csv, report, row);
    for (const BenchRow& row : report.pooled)
        appendRow(csv, report, row);
    return csv;
}

} // namespace px

#include "parallax/eval/BenchCsv.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <optional>
#include <vector>

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
        row.gpuStats ? row.gpuKernels : "",
        row.gpuStats ? number("%.9g", row.gpuStats->meanError) : "",
        row.gpuStats ? number("%.9g", row.gpuStats->p99Error) : "",
        row.gpuStats ? number("%.9g", row.gpuStats->maxError) : "",
        row.gpuStats ? number("%.9g", row.gpuStats->meanFetches) : "",
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

namespace px {
namespace {

// Splits one CSV record (RFC 4180 quoting) starting at `pos`; advances `pos` past its line end.
std::vector<std::string> readRecord(std::string_view text, std::size_t& pos) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (; pos < text.size(); ++pos) {
        const char c = text[pos];
        if (quoted) {
            if (c == '"' && pos + 1 < text.size() && text[pos + 1] == '"') {
                fields.back() += '"';
                ++pos;
            } else if (c == '"') {
                quoted = false;
            } else {
                fields.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else if (c == '\n') {
            ++pos;
            break;
        } else if (c != '\r') {
            fields.back() += c;
        }
    }
    return fields;
}

template <typename T> bool parseNumber(const std::string& text, T& value) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end;
}

} // namespace

Result<BenchReport> parseBenchCsv(std::string_view text, const std::string& source) {
    std::size_t pos = 0;
    const std::vector<std::string> header = readRecord(text, pos);
    std::string joined;
    for (const std::string& h : header)
        joined += (joined.empty() ? "" : ",") + h;
    if (joined != kBenchCsvHeader && joined != kBenchCsvHeaderV1)
        return fileError(source, "not a bench report: the header differs from the bench's");
    const bool gpuErrors = joined == kBenchCsvHeader;
    BenchReport report;
    report.polarDeg.clear();
    int line = 1;
    while (pos < text.size()) {
        ++line;
        const std::vector<std::string> f = readRecord(text, pos);
        if (f.size() == 1 && f[0].empty())
            continue;
        auto bad = [&](const std::string& what) {
            return fileError(source, "line " + std::to_string(line) + ": " + what);
        };
        if (f.size() != header.size())
            return bad(std::to_string(f.size()) + " fields, expected " +
                       std::to_string(header.size()));
        BenchRow row;
        row.map = f[0];
        row.pooled = f[0] == "all" && f[1].empty();
        const std::optional<Technique> technique = parseTechnique(f[8]);
        if (!technique)
            return bad("unknown technique '" + f[8] + "'");
        row.setting.technique = *technique;
        row.setting.params = info(*technique).defaults;
        row.setting.label = f[9];
        row.setting.isDefault = f[10] == "1";
        const std::optional<WrapMode> wrap = parseWrapMode(f[3]);
        bool ok = wrap.has_value() && parseNumber(f[5], row.polarDeg) &&
                  parseNumber(f[6], report.azimuthDeg) && parseNumber(f[7], report.rays);
        if (wrap)
            report.wrap = *wrap;
        if (!row.pooled) {
            float scale = 0.0f;
            ok = ok && parseNumber(f[1], row.width) && parseNumber(f[2], row.height) &&
                 parseNumber(f[4], scale);
            row.scale = scale;
        }
        int* params[] = {&row.setting.params.minLayers, &row.setting.params.maxLayers,
                         &row.setting.params.binarySteps, &row.setting.params.secantSteps,
                         &row.setting.params.maxSteps};
        for (int k = 0; k < 5; ++k) {
            if (!f[11 + k].empty())
                ok = ok && parseNumber(f[11 + k], *params[k]);
        }
        HitErrorStats& s = row.stats;
        ok = ok && parseNumber(f[16], s.meanError) && parseNumber(f[17], s.p99Error) &&
             parseNumber(f[18], s.maxError) && parseNumber(f[19], s.wrongSurface) &&
             parseNumber(f[20], s.invalid) && parseNumber(f[21], s.meanFetches) &&
             parseNumber(f[22], s.p99Fetches) && parseNumber(f[23], s.maxFetches);
        for (auto [k, target] : {std::pair{24, &row.cpuNsPerRay}, {25, &row.gpuMsPerFrame}}) {
            double value = 0.0;
            if (!f[k].empty()) {
                ok = ok && parseNumber(f[k], value);
                *target = value;
            }
        }
        if (!ok)
            return bad("a value is not a number");
        row.gpuRenderer = f[26];
        if (gpuErrors && !f[27].empty()) {
            HitErrorStats g;
            if (!(parseNumber(f[28], g.meanError) && parseNumber(f[29], g.p99Error) &&
                  parseNumber(f[30], g.maxError) && parseNumber(f[31], g.meanFetches)))
                return bad("a value is not a number");
            row.gpuKernels = f[27];
            row.gpuStats = g;
        }
        if (std::find(report.polarDeg.begin(), report.polarDeg.end(), row.polarDeg) ==
            report.polarDeg.end())
            report.polarDeg.push_back(row.polarDeg);
        (row.pooled ? report.pooled : report.rows).push_back(std::move(row));
    }
    if (report.rows.empty() && report.pooled.empty())
        return fileError(source, "the bench report has no rows");
    if (!report.pooled.empty())
        report.gpuNote = report.pooled.front().gpuRenderer;
    return report;
}

} // namespace px

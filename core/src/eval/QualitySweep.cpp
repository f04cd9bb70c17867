#include "parallax/eval/QualitySweep.h"

#include "parallax/NumberText.h"
#include "parallax/trace/Tracer.h"

#include <algorithm>
#include <cstdio>

namespace px {
namespace {

TraceParams withLayers(Technique t, int minLayers, int maxLayers) {
    TraceParams p = info(t).defaults;
    p.minLayers = minLayers;
    p.maxLayers = maxLayers;
    return p;
}

TraceParams withSteps(Technique t, int maxSteps) {
    TraceParams p = info(t).defaults;
    p.maxSteps = maxSteps;
    return p;
}

bool sameParams(const TraceParams& a, const TraceParams& b) {
    return a.minLayers == b.minLayers && a.maxLayers == b.maxLayers &&
           a.binarySteps == b.binarySteps && a.secantSteps == b.secantSteps &&
           a.maxSteps == b.maxSteps;
}

std::string trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string_view::npos)
        return {};
    const auto last = s.find_last_not_of(" \t");
    return std::string(s.substr(first, last - first + 1));
}

} // namespace

std::string settingLabel(Technique technique, const TraceParams& p) {
    const TechniqueInfo& ti = info(technique);
    std::string label;
    auto append = [&](const std::string& part) { label += label.empty() ? part : ", " + part; };
    if (ti.usesLayers)
        append("layers " + std::to_string(p.minLayers) + "-" + std::to_string(p.maxLayers));
    // The reference's cap is a safety net, not a quality knob: leave it out of its label.
    if (ti.usesMaxSteps && technique != Technique::Exact)
        append((technique == Technique::Pyramid ? "nodes " : "steps ") +
               std::to_string(p.maxSteps));
    if (ti.usesBinarySteps)
        append("binary " + std::to_string(p.binarySteps));
    if (ti.usesSecantSteps)
        append("secant " + std::to_string(p.secantSteps));
    return label;
}

BenchSetting defaultSetting(Technique technique) {
    const TraceParams& p = info(technique).defaults;
    return BenchSetting{technique, p, settingLabel(technique, p), true};
}

std::vector<BenchSetting> qualitySweep(Technique technique) {
    std::vector<TraceParams> points;
    switch (technique) {
    case Technique::Steep:
    case Technique::Pom:
    case Technique::Relief:
    case Technique::Secant:
        // The tutorial shaders' quality range (8-32) and its halves and doubles: layers scale by
        // view angle.
        for (auto [lo, hi] : {std::pair{4, 16}, {8, 32}, {16, 64}, {32, 128}, {64, 256}})
            points.push_back(withLayers(technique, lo, hi));
        break;
    case Technique::Cone:
        for (int steps : {8, 16, 32, 64, 128, 256})
            points.push_back(withSteps(technique, steps));
        break;
    case Technique::RelaxedCone:
        for (int steps : {4, 8, 12, 16, 24, 32, 48, 64})
            points.push_back(withSteps(technique, steps));
        break;
    case Technique::Pyramid:
        // Exact when the cap is not reached; low caps show what a shader budget would cost.
        for (int nodes : {16, 32, 64, 128, 256})
            points.push_back(withSteps(technique, nodes));
        break;
    case Technique::None:
    case Technique::Normal:
    case Technique::Offset:
    case Technique::Exact:
        break;
    }
    const TraceParams& defaults = info(technique).defaults;
    if (std::none_of(points.begin(), points.end(),
                     [&](const TraceParams& p) { return sameParams(p, defaults); }))
        points.push_back(defaults);

    std::vector<BenchSetting> sweep;
    sweep.reserve(points.size());
    for (const TraceParams& p : points)
        sweep.push_back({technique, p, settingLabel(technique, p), sameParams(p, defaults)});
    return sweep;
}

Result<std::vector<BenchSetting>> parseSweep(std::string_view spec) {
    const std::size_t colon = spec.find(':');
    const std::size_t equals = spec.find('=');
    if (colon == std::string_view::npos || equals == std::string_view::npos || equals < colon)
        return Error{"a sweep is TECHNIQUE:PARAMETER=V1,V2,..., not '" + std::string(spec) + "'"};
    const std::string name = trim(spec.substr(0, colon));
    const std::string parameter = trim(spec.substr(colon + 1, equals - colon - 1));
    const std::optional<Technique> technique = parseTechnique(name);
    if (!technique || !info(*technique).parallax)
        return Error{"unknown technique '" + name + "' in the sweep"};
    const TechniqueInfo& ti = info(*technique);
    const bool reads = parameter == "layers"         ? ti.usesLayers
                       : parameter == "binary-steps" ? ti.usesBinarySteps
                       : parameter == "secant-steps" ? ti.usesSecantSteps
                       : parameter == "max-steps"    ? ti.usesMaxSteps
                                                     : false;
    if (!reads) {
        // Name only the parameters this technique reads, so the list is the way out.
        std::string known;
        for (const auto& [flag, parameterName] :
             {std::pair{ti.usesLayers, "layers"}, std::pair{ti.usesBinarySteps, "binary-steps"},
              std::pair{ti.usesSecantSteps, "secant-steps"},
              std::pair{ti.usesMaxSteps, "max-steps"}}) {
            if (flag)
                known += (known.empty() ? "" : ", ") + std::string(parameterName);
        }
        return Error{
            name + " has no parameter '" + parameter + "'" +
            (known.empty() ? std::string(": it reads none") : " (it reads " + known + ")")};
    }
    std::vector<BenchSetting> sweep;
    std::string_view values = spec.substr(equals + 1);
    std::size_t start = 0;
    while (start <= values.size()) {
        const std::size_t comma = std::min(values.find(',', start), values.size());
        const std::string value = trim(values.substr(start, comma - start));
        start = comma + 1;
        TraceParams p = ti.defaults;
        // One integer, or MIN-MAX for layers, each within the parameter's range (never wrapped).
        const std::string what = name + ":" + parameter;
        const std::size_t dash = parameter == "layers" ? value.find('-', 1) : std::string::npos;
        if (parameter == "layers" && dash == std::string::npos)
            return Error{"'" + value + "' is not a value of layers (MIN-MAX)"};
        const long long low = parameter == "layers" ? 1 : parameter == "max-steps" ? 1 : 0;
        const long long high = parameter == "layers"      ? kMaxLayersLimit
                               : parameter == "max-steps" ? kMaxStepsLimit
                                                          : kMaxRefineLimit;
        Result<long long> first = parseInteger(value.substr(0, dash), what, low, high);
        if (!first)
            return first.error();
        Result<long long> second = dash == std::string::npos
                                       ? first
                                       : parseInteger(value.substr(dash + 1), what, low, high);
        if (!second)
            return second.error();
        const int a = static_cast<int>(*first), b = static_cast<int>(*second);
        if (parameter == "layers") {
            p.minLayers = a;
            p.maxLayers = b;
        } else {
            (parameter == "binary-steps"   ? p.binarySteps
             : parameter == "secant-steps" ? p.secantSteps
                                           : p.maxSteps) = a;
        }
        if (Status v = validate(p); !v)
            return v.error().prefixed(name + ": ");
        sweep.push_back({*technique, p, settingLabel(*technique, p), sameParams(p, ti.defaults)});
    }
    return sweep;
}

Result<std::vector<Technique>> parseTechniqueList(std::string_view list) {
    std::vector<Technique> techniques;
    if (trim(list) == "all") {
        for (const TechniqueInfo& ti : allTechniques()) {
            if (ti.parallax)
                techniques.push_back(ti.id);
        }
        return techniques;
    }
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = trim(list.substr(start, comma - start));
        start = comma + 1;
        const std::optional<Technique> t = parseTechnique(name);
        if (!t)
            return Error{"unknown technique '" + name + "' in the technique list"};
        if (!info(*t).parallax)
            return Error{"'" + name + "' traces no rays: there is nothing to measure"};
        if (std::find(techniques.begin(), techniques.end(), *t) != techniques.end())
            return Error{"technique '" + name + "' is listed twice"};
        techniques.push_back(*t);
    }
    return techniques;
}

} // namespace px

#include "CommonOptions.h"

#include "parallax/NumberText.h"
#include "parallax/material/MaterialNames.h"

#include <climits>
#include <cstdint>
#include <cstdlib>
#include <functional>

namespace px::cli {

std::vector<std::string> choices(std::span<const std::string_view> names) {
    return {names.begin(), names.end()};
}

namespace {

CLI::Validator numberCheck(NumberRange range, std::string description) {
    return CLI::Validator(
        [range](std::string& value) -> std::string {
            Result<double> n = parseReal(value, {}, range);
            return n ? std::string() : n.error().message;
        },
        std::move(description));
}

} // namespace

CLI::Validator inRange(double min, double max) {
    return numberCheck({min, max}, "[" + std::to_string(min) + " - " + std::to_string(max) + "]");
}

CLI::Validator positive() {
    return numberCheck({0.0, NumberRange{}.max, true}, "POSITIVE");
}

CLI::Validator nonNegative() {
    return numberCheck({0.0, NumberRange{}.max}, "NONNEGATIVE");
}

void checkNumbers(CLI::App& app) {
    for (CLI::App* command : app.get_subcommands({})) {
        for (CLI::Option* option : command->get_options()) {
            const std::string full = option->get_type_name();
            const std::string type = full.substr(0, full.find(':'));
            if (type == "FLOAT") {
                option->transform(CLI::Validator(
                    [](std::string& value) -> std::string {
                        Result<double> n = parseReal(value);
                        return n ? std::string() : n.error().message;
                    },
                    "", "number"));
            } else if (type == "INT" || type == "UINT") {
                const long long min = type == "INT" ? INT_MIN : 0;
                const long long max = type == "INT" ? INT_MAX : UINT32_MAX;
                option->transform(CLI::Validator(
                    [min, max](std::string& value) -> std::string {
                        Result<long long> n = parseInteger(value, {}, min, max);
                        if (!n)
                            return n.error().message;
                        value = std::to_string(*n); // decimal for CLI11: "010" is ten
                        return {};
                    },
                    "", "integer"));
            }
        }
    }
}

void HeightOptions::addTo(CLI::App& command, bool required) {
    auto* height = command.add_option(
        "--height", file,
        "Height map (PNG, TIFF, EXR, BMP, JPEG, TGA, HDR, ...: docs/image-files.md)");
    if (required)
        height->required();
    command.add_flag("--invert", invert, "The file is a depth map (white = deep)");
    command.add_flag("--normalize", normalize, "Remap the map's [min, max] to [0, 1]");
    command.add_flag("--allow-large", allowLarge, "Accept maps with a side over 16384 texels");
    command.add_option("--layer", layer,
                       "The part or layer of a multi-part or layered EXR to read the height from");
    command
        .add_option("--page", page, "The page of a multi-page TIFF (or EXR part) to read, from 0")
        ->check(CLI::NonNegativeNumber);
    command.add_option("--channel", channel, "Channel holding the height")
        ->check(CLI::IsMember(choices(heightChannelNames())));
    command.add_option("--wrap", wrap, "Wrap mode of the material")
        ->check(CLI::IsMember({"repeat", "clamp"}));
}

WrapMode HeightOptions::wrapMode() const {
    return parseWrapMode(wrap).value_or(WrapMode::Repeat);
}

Result<HeightField> HeightOptions::load() const {
    HeightLoadOptions options;
    options.channel = parseHeightChannel(channel).value_or(HeightChannel::Red);
    options.invert = invert;
    options.normalize = normalize;
    options.allowLarge = allowLarge;
    options.layer = layer;
    options.page = page;
    return loadHeightField(file, options);
}

namespace {

// "default: pom 8, relief 8, ..." for the techniques that read the parameter.
std::string defaultsOf(const std::function<bool(const TechniqueInfo&)>& reads,
                       int TraceParams::*field) {
    std::string text;
    for (const TechniqueInfo& t : allTechniques()) {
        if (!reads(t))
            continue;
        text += (text.empty() ? " (default: " : ", ") + std::string(t.name) + " " +
                std::to_string(t.defaults.*field);
    }
    return text.empty() ? text : text + ")";
}

} // namespace

void QualityOptions::addTo(CLI::App& command) {
    auto layers = [](const TechniqueInfo& t) { return t.usesLayers; };
    command
        .add_option("--min-layers", minLayers,
                    "Layers looking straight down" + defaultsOf(layers, &TraceParams::minLayers))
        ->check(inRange(1, kMaxLayersLimit));
    command
        .add_option("--max-layers", maxLayers,
                    "Layers at grazing angles" + defaultsOf(layers, &TraceParams::maxLayers))
        ->check(inRange(1, kMaxLayersLimit));
    command
        .add_option("--binary-steps", binarySteps,
                    "Binary search steps" +
                        defaultsOf([](const TechniqueInfo& t) { return t.usesBinarySteps; },
                                   &TraceParams::binarySteps))
        ->check(inRange(0, kMaxRefineLimit));
    command
        .add_option("--secant-steps", secantSteps,
                    "Secant steps" +
                        defaultsOf([](const TechniqueInfo& t) { return t.usesSecantSteps; },
                                   &TraceParams::secantSteps))
        ->check(inRange(0, kMaxRefineLimit));
    command
        .add_option("--max-steps", maxSteps,
                    "Cap on cone steps, cells or pyramid nodes" +
                        defaultsOf([](const TechniqueInfo& t) { return t.usesMaxSteps; },
                                   &TraceParams::maxSteps))
        ->check(inRange(1, kMaxStepsLimit));
}

void QualityOptions::applyTo(TraceParams& params) const {
    params.minLayers = minLayers.value_or(params.minLayers);
    params.maxLayers = maxLayers.value_or(params.maxLayers);
    params.binarySteps = binarySteps.value_or(params.binarySteps);
    params.secantSteps = secantSteps.value_or(params.secantSteps);
    params.maxSteps = maxSteps.value_or(params.maxSteps);
}

void KernelOptions::addTo(CLI::App& command) {
    command
        .add_option("--kernels", name,
                    "GPU kernels: production (hardware filtering and gathers, as an engine "
                    "samples) or verify (texel reads filtered in shader code: equal to the CPU)")
        ->check(CLI::IsMember({"production", "verify"}));
}

KernelFlavour KernelOptions::flavour() const {
    return shader::parseKernelFlavour(name).value_or(KernelFlavour::Production);
}

void ConeCacheOptions::addTo(CLI::App& command) {
    command.add_option("--cache", value,
                       "Folder keeping baked cone maps between runs, or 'off' (default: "
                       "$XDG_CACHE_HOME/parallax-studio/cone-maps)");
}

std::string ConeCacheOptions::folder() const {
    if (value == "off")
        return {};
    if (!value.empty())
        return value;
    // The XDG base directory spec: a relative path in XDG_CACHE_HOME is invalid and ignored (it
    // would make a cache folder wherever the command runs); so is a relative HOME.
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    if (xdg && *xdg == '/')
        return std::string(xdg) + "/parallax-studio/cone-maps";
    if (home && *home == '/')
        return std::string(home) + "/.cache/parallax-studio/cone-maps";
    return {};
}

} // namespace px::cli

#pragma once
// Options several subcommands share: the height map and how to read it, and the quality
// parameters of the techniques.

#include "parallax/Result.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/shader/VariantKey.h"
#include "parallax/trace/Technique.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace px::cli {

// The names of a core table as CLI11's IsMember wants them, so no command lists them by hand.
std::vector<std::string> choices(std::span<const std::string_view> names);

// Numbers on the command line, read by parallax/NumberText.h and refused in its words
// ("--level: 'nan' is not a finite number", "--size: '0' is out of range (1 to 16384)").
// checkNumbers puts the reading in front of every numeric option of every command: a FLOAT must be
// finite, an INT fit an int and a UINT an unsigned 32-bit integer, decimal (CLI11 alone reads
// "010" as octal and wraps what overflows). Ranges are checked by these validators:
CLI::Validator inRange(double min, double max);
CLI::Validator positive();    // > 0
CLI::Validator nonNegative(); // >= 0
void checkNumbers(CLI::App& app);

struct HeightOptions {
    std::string file;
    bool invert = false;
    bool normalize = false;
    bool allowLarge = false;
    std::string layer; // of a multi-part or layered EXR
    int page = -1;     // of a multi-page TIFF (or an EXR's part by number)
    std::string channel = "red";
    std::string wrap = "repeat";

    // Adds --height, --invert, --normalize, --allow-large, --layer, --page, --channel, --wrap.
    void addTo(CLI::App& command, bool required = true);
    WrapMode wrapMode() const;
    Result<HeightField> load() const;
};

// The parameters artists tune; each left out keeps the technique's default (the help says which).
struct QualityOptions {
    std::optional<int> minLayers, maxLayers, binarySteps, secantSteps, maxSteps;

    // Adds --min-layers, --max-layers, --binary-steps, --secant-steps, --max-steps.
    void addTo(CLI::App& command);
    // Overrides the parameters given on the command line.
    void applyTo(TraceParams& params) const;
};

// The GPU kernels' flavour (VariantKey.h): production as an engine samples, or verify, the
// kernels that match the CPU to the bit.
struct KernelOptions {
    std::string name = "production";

    // Adds --kernels production|verify.
    void addTo(CLI::App& command);
    KernelFlavour flavour() const;
};

// Where technique auto and `recommend` keep baked cone maps between runs (docs/recommend.md).
struct ConeCacheOptions {
    std::string value; // empty: the user's cache folder; "off": none

    // Adds --cache DIR|off.
    void addTo(CLI::App& command);
    // The folder: $XDG_CACHE_HOME/parallax-studio/cone-maps, else ~/.cache/..., by default (a
    // relative XDG_CACHE_HOME is ignored, as the XDG spec says); empty for "off", or when neither
    // variable is set to an absolute path.
    std::string folder() const;
};

} // namespace px::cli

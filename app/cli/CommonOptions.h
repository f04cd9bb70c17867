#pragma once
// Options several subcommands share: the height map and how to read it.

#include "parallax/Result.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/heightfield/WrapMode.h"

#include <CLI/CLI.hpp>
#include <string>

namespace px::cli {

struct HeightOptions {
    std::string file;
    bool invert = false;
    bool normalize = false;
    bool allowLarge = false;
    std::string channel = "red";
    std::string wrap = "repeat";

    // Adds --height, --invert, --normalize, --allow-large, --channel, --wrap.
    void addTo(CLI::App& command, bool required = true);
    WrapMode wrapMode() const;
    Result<HeightField> load() const;
};

} // namespace px::cli

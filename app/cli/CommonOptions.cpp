#include "CommonOptions.h"

namespace px::cli {

void HeightOptions::addTo(CLI::App& command, bool required) {
    auto* height =
        command.add_option("--height", file, "Height map (PNG, TIFF, EXR, BMP, JPEG, TGA)");
    if (required)
        height->required();
    command.add_flag("--invert", invert, "The file is a depth map (white = deep)");
    command.add_flag("--normalize", normalize, "Remap the map's [min, max] to [0, 1]");
    command.add_flag("--allow-large", allowLarge, "Accept maps with a side over 16384 texels");
    command.add_option("--channel", channel, "Channel holding the height")
        ->check(CLI::IsMember({"red", "green", "blue", "alpha", "luminance"}));
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
    return loadHeightField(file, options);
}

} // namespace px::cli

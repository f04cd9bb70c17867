#pragma once
// Loading a height map from an image file.

#include "parallax/Result.h"
#include "parallax/heightfield/HeightField.h"

#include <optional>
#include <string>
#include <string_view>

namespace px {

enum class HeightChannel { Red, Green, Blue, Alpha, Luminance };

std::optional<HeightChannel> parseHeightChannel(std::string_view name);

struct HeightLoadOptions {
    HeightChannel channel = HeightChannel::Red; // grey images have only one channel: that one
    bool invert = false;                        // depth map (white = deep): h = 1 - value
    bool allowLarge = false;                    // sides over 16384 are refused otherwise
    bool normalize =
        false; // remap [min,max] to [0,1]; without it values outside [0,1] are an error
};

// Errors name the file and the problem: unreadable, not an image, truncated, zero size,
// too large, NaN/Inf texels (with their count and the first position), a missing channel,
// values outside [0,1] in a float file (reported, never clamped silently).
Result<HeightField> loadHeightField(const std::string& path, const HeightLoadOptions& options = {});

// Extracts one height channel from an image already in memory; `source` names it in errors. A
// one-channel image moved in gives its texels to the field (shared, not copied).
Result<HeightField> heightFieldFromImage(Image image, const HeightLoadOptions& options,
                                         const std::string& source);

} // namespace px

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

// The file values a height map's 0 and 1 stand for: h = (value - lo) / (hi - lo), lo < hi. Float
// height maps come in their maker's units, signed or in any range (world-space bakes, some
// libraries' EXRs); a material records the range so the file is read as it is (conventions §2).
struct HeightRange {
    float lo = 0.0f;
    float hi = 1.0f;
    bool operator==(const HeightRange&) const = default;
};

struct HeightLoadOptions {
    HeightChannel channel = HeightChannel::Red; // grey images have only one channel: that one
    bool invert = false;                        // depth map (white = deep): h = 1 - value
    bool allowLarge = false;                    // sides over 16384 are refused otherwise
    std::string layer; // a multi-part or layered EXR's part or layer (ImageReadOptions::layer)
    int page = -1;     // a multi-page TIFF's page, an EXR's part by number (ImageReadOptions::page)
    bool normalize =
        false; // remap [min,max] to [0,1]; without it values outside [0,1] are an error
    // Set: values in [lo, hi] read as [0, 1], any value outside it is an error (the file is not
    // the one the range was recorded from). Applied before `normalize` and `invert`.
    std::optional<HeightRange> range;
};

// Errors name the file and the problem: unreadable, not an image, truncated, zero size,
// too large, NaN/Inf texels (with their count and the first position), a missing channel,
// values outside [0,1] in a float file (reported, never clamped silently).
Result<HeightField> loadHeightField(const std::string& path, const HeightLoadOptions& options = {});

// Extracts one height channel from an image already in memory; `source` names it in errors. A
// one-channel image moved in gives its texels to the field (shared, not copied).
Result<HeightField> heightFieldFromImage(Image image, const HeightLoadOptions& options,
                                         const std::string& source);

// A height map read for a material, the range it needs found from the file: values within [0, 1]
// as stored (no range); within `options.range` (the range the material recorded), by that range;
// otherwise (a float map in its own units) over the file's own [min, max], which is returned for
// the material to record. `normalize` is ignored. Errors: as loadHeightField, and a file whose
// texels all hold one value outside [0, 1] (no range to read a relief by).
struct FittedHeight {
    HeightField field;
    std::optional<HeightRange> range;
};
Result<FittedHeight> fitHeightField(Image image, const HeightLoadOptions& options,
                                    const std::string& source);
Result<FittedHeight> loadHeightFieldFitted(const std::string& path,
                                           const HeightLoadOptions& options = {});

} // namespace px

#pragma once
// Reading and writing image files: PNG by the core's own libpng codec, other formats by OpenImageIO
// in a module loaded on first need (src/image/ImageModule.h); no library type leaks out.
// Failures come back as a sentence naming the file; writes are atomic: the data goes to a
// temporary file in the target's folder which is then renamed, so a failed or cancelled write
// never leaves half a file and never touches an existing target.

#include "parallax/Result.h"
#include "parallax/image/Image.h"

#include <limits>
#include <string>

namespace px {

struct ImageReadOptions {
    int maxSide = 16384;         // larger images are refused unless this is raised
    bool rejectNonFinite = true; // NaN/Inf texels are an error (count and first position)
    // Texels of larger magnitude are an error naming the first, the limit and `limitReason`
    // (why the reader cannot use them): a float file's 3e38 is finite, but overflows what the
    // renderer computes from it, and one infinite texel turns a whole channel black.
    float maxMagnitude = std::numeric_limits<float>::infinity();
    std::string limitReason;
    // Which image of a file that holds several: a TIFF page or an EXR part counted from 0, an
    // EXR part or channel layer ("height" for height.Y) by name. A file with several and no
    // choice is refused with the list (docs/image-files.md).
    std::string layer;
    int page = -1;
};

// The most a colour (albedo) map may hold as stored: the renderer decodes sRGB into 16-bit floats,
// which overflow from about 100 on. Float files may stray a little past 0 to 1; not that far.
ImageReadOptions colourMapReading();

// Reads every channel of the image (or the chosen page, part or layer) as float, values as stored
// (8/16-bit scaled to [0,1], float verbatim), turned upright by the file's orientation. The file
// is read once through the descriptor it was opened by; its format is told by its content. Errors:
// missing or unreadable file, not an image, damaged or truncated data, a claim larger than the
// file can hold or the process can allocate (checked before any texel memory is taken), zero
// size, a side over maxSide, several images and none chosen, NaN/Inf texels, texels over
// maxMagnitude. What the reader did beyond decoding (a turn, the part read) goes to the note sink.
Result<Image> readImage(const std::string& path, const ImageReadOptions& options = {});

// Where readImage's notes go: by default stderr as "note: FILE: ..."; the editor sets its own.
using ImageNoteSink = void (*)(const std::string& note);
void setImageNoteSink(ImageNoteSink sink);

enum class PixelFormat { UInt8, UInt16, Half, Float };

struct ImageWriteOptions {
    PixelFormat format = PixelFormat::UInt8;
    bool srgb = false; // tags the file as sRGB (albedo); pixel values are written as given
};

// The pixel format a bit count names: 8, 16, or 32 (float). Others are an error.
Result<PixelFormat> pixelFormatFromBits(int bits);

// True if the file's extension names a format that can store `format` (e.g. PNG has no float).
bool extensionSupports(const std::string& path, PixelFormat format);

// Writes atomically. Integer formats clamp to [0,1] and round to nearest; callers that need
// another rounding (cone maps round down) quantise before calling.
Status writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options);

} // namespace px

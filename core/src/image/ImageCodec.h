#pragma once
// One image file opened for reading, whoever decodes it: the core's own PNG reader (PngCodec.h)
// or OpenImageIO in its module (ImageModule.h). readImage (ImageFile.cpp) judges the header
// before it lets a decoder allocate anything.

#include "parallax/Result.h"

#include <cstdint>
#include <memory>
#include <string>

namespace px {

struct ImageHeader {
    int width = 0, height = 0, channels = 0, depth = 1;
    std::int64_t bitsPerTexel = 0; // all channels as stored in the file (1-bit PNGs exist)
    std::string format;            // OpenImageIO's format name: "png", "jpeg", "openexr", ...
    std::string compression;       // its "compression" attribute (TIFF, EXR): "zip", ...
    bool alphaOnly = false;        // one channel, which the file names alpha (an EXR's "A")
    int orientation = 1;           // EXIF/TIFF Orientation, 1 to 8 (a +Y Radiance file: 4)
    std::string chosen;            // the page, part or layer read, as the error lists name them
};

// What readImage asks a decoder for: the file's whole content, read once through its descriptor,
// and the format its signature names (ImageFormat.h); the page or layer as ImageReadOptions says.
struct ImageSource {
    std::string path; // for messages only: nothing opens it again
    std::string format;
    std::shared_ptr<const std::string> bytes; // shared with readImage, which bounds the claim
    std::string layer;
    int page = -1;
};

class ImageDecoder {
public:
    ImageDecoder() = default;
    ImageDecoder(const ImageDecoder&) = delete;
    ImageDecoder& operator=(const ImageDecoder&) = delete;
    virtual ~ImageDecoder() = default;

    virtual const ImageHeader& header() const = 0;
    // Every channel of the chosen subimage (or layer) as float into width * height * channels
    // values, 8 and 16 bits scaled to [0, 1], floats verbatim. An error is the problem without the
    // file name.
    virtual Status read(float* texels) = 0;
};

} // namespace px

#pragma once
// OpenImageIO, loaded on first need from a module of its own (libparallax-oiio.so): its 260
// libraries take about half a second of CPU to load, in every run of the command line, and most
// runs read and write only PNG (PngCodec.h). Every other format, the environment's resampling and
// the JPEG map class go through here. The module is built from the same tree; it is found next to
// the program as installed (../lib/parallax-studio/), else where the build put it, or where
// PX_IMAGE_MODULE names it.

#include "ImageCodec.h"
#include "parallax/image/ImageFile.h"

#include <memory>
#include <string>
#include <vector>

namespace px {

// Bumped with any change to ImageModule: a module of another build is refused, not called.
constexpr int kImageModuleAbi = 2;

struct ImageModule {
    int abi;
    const char* version; // the project version it was built as (Version.h)
    // A decoder of the source's bytes (never its path): an error lists the pages, parts or
    // layers when the file has several and the source chooses none, or not one of them.
    Result<std::unique_ptr<ImageDecoder>> (*open)(const ImageSource& source);
    // The file's bytes, encoded for the format `path`'s extension names.
    Result<std::vector<unsigned char>> (*encode)(const std::string& path, const Image& image,
                                                 const ImageWriteOptions& options);
    // A tent filter as wide as the ratio (OpenImageIO's "triangle").
    Image (*resize)(const Image& image, int width, int height);
    // 8-bit grey texels encoded as a JPEG of that quality in memory and decoded back.
    Result<std::vector<unsigned char>> (*throughJpeg)(const std::vector<unsigned char>& grey,
                                                      int width, int height, int quality);
};

// The module, loaded on the first call (thread-safe); the error says what was looked for where.
Result<const ImageModule*> imageModule();

// True once the module is loaded (a test checks that PNG work never loads it).
bool imageModuleLoaded();

} // namespace px

// The module's one entry point.
extern "C" const px::ImageModule* pxImageModule();

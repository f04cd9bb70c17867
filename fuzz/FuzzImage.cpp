// Fuzz target: the image import path (readImage through OpenImageIO, then the height map
// extraction with every channel option). The first byte picks the file extension, so one corpus
// covers every format; the rest is the file.

#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

constexpr const char* kExtensions[] = {".png", ".exr", ".tif", ".bmp", ".jpg", ".tga", ".hdr"};
constexpr std::size_t kExtensionCount = sizeof kExtensions / sizeof kExtensions[0];

std::string inputPath(std::uint8_t selector) {
    static const std::filesystem::path folder = [] {
        auto f = std::filesystem::temp_directory_path() /
                 ("px-fuzz-image-" + std::to_string(::getpid()));
        std::filesystem::create_directories(f);
        return f;
    }();
    return (folder / (std::string("input") + kExtensions[selector % kExtensionCount])).string();
}

// Every height that got through lies in [0, 1] (a NaN fails the test too).
void checkUnit(const px::SharedTexels<float>& texels) {
    for (const float h : texels) {
        if (!(h >= 0.0f && h <= 1.0f)) {
            std::fprintf(stderr, "height %g escaped the checks\n", h);
            std::abort();
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1)
        return 0;
    const std::string path = inputPath(data[0]);
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    }
    px::ImageReadOptions read;
    read.maxSide = 1024; // sizes the header claims are allocated: keep them within the fuzzer's RSS
    px::Result<px::Image> image = px::readImage(path, read);
    if (!image) {
        if (image.error().message.rfind(path, 0) != 0) {
            std::fprintf(stderr, "error without its file name: %s\n",
                         image.error().message.c_str());
            std::abort();
        }
        return 0;
    }
    if (image->pixels.size() !=
        static_cast<std::size_t>(image->width) * image->height * image->channels)
        std::abort();
    for (const px::HeightChannel channel :
         {px::HeightChannel::Red, px::HeightChannel::Green, px::HeightChannel::Blue,
          px::HeightChannel::Alpha, px::HeightChannel::Luminance}) {
        for (const bool normalize : {false, true}) {
            px::HeightLoadOptions options;
            options.channel = channel;
            options.normalize = normalize;
            options.invert = normalize;
            px::Result<px::HeightField> field = px::heightFieldFromImage(*image, options, path);
            if (field)
                checkUnit(field->texels);
            // Read by its own range as import does: still [0, 1], from a range with lo < hi.
            px::Result<px::FittedHeight> fitted = px::fitHeightField(*image, options, path);
            if (fitted) {
                checkUnit(fitted->field.texels);
                if (fitted->range && !(fitted->range->lo < fitted->range->hi))
                    std::abort();
            }
        }
    }
    return 0;
}

#include "parallax/image/ImageFile.h"

#include "ExrHeaderCheck.h"
#include "ImageBudget.h"
#include "PngCheck.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/FileExtension.h"
#include "parallax/io/Inputs.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <new>
#include <system_error>

namespace px {
namespace {

// OIIO's messages end with newlines and sometimes repeat the file name; keep one clean line.
std::string oiioMessage(std::string message) {
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        message.pop_back();
    std::replace(message.begin(), message.end(), '\n', ' ');
    return message.empty() ? std::string("unknown image library error") : message;
}

OIIO::TypeDesc typeOf(PixelFormat format) {
    switch (format) {
    case PixelFormat::UInt8:
        return OIIO::TypeDesc::UINT8;
    case PixelFormat::UInt16:
        return OIIO::TypeDesc::UINT16;
    case PixelFormat::Half:
        return OIIO::TypeDesc::HALF;
    case PixelFormat::Float:
        return OIIO::TypeDesc::FLOAT;
    }
    return OIIO::TypeDesc::UINT8;
}

Status checkFinite(const std::string& path, const Image& image) {
    std::size_t count = 0;
    std::size_t first = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        if (!std::isfinite(image.pixels[i])) {
            if (count++ == 0)
                first = i;
        }
    }
    if (count == 0)
        return success();
    const std::size_t texel = first / image.channels;
    const int x = static_cast<int>(texel % image.width);
    const int y = static_cast<int>(texel / image.width);
    return fileError(path, std::to_string(count) + " NaN or infinite value" +
                               (count == 1 ? "" : "s") + ", the first at texel (" +
                               std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                               std::to_string(first % image.channels));
}

// The first texel of magnitude over `limit`, named with the limit and why it is one.
Status checkMagnitude(const std::string& path, const Image& image, float limit,
                      const std::string& why) {
    if (std::isinf(limit))
        return success();
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        if (std::abs(image.pixels[i]) <= limit)
            continue;
        const std::size_t texel = i / image.channels;
        char value[32], bound[32];
        std::snprintf(value, sizeof value, "%g", static_cast<double>(image.pixels[i]));
        std::snprintf(bound, sizeof bound, "%g", static_cast<double>(limit));
        return fileError(path, "texel (" + std::to_string(texel % image.width) + ", " +
                                   std::to_string(texel / image.width) + ") channel " +
                                   std::to_string(i % image.channels) + " holds " + value +
                                   ", beyond the " + bound + " " + why);
    }
    return success();
}

} // namespace

ImageReadOptions colourMapReading() {
    ImageReadOptions read;
    read.maxMagnitude = 100.0f;
    read.limitReason = "a colour map may hold (its 16-bit float texture would overflow and the "
                       "channel render black; a colour is 0 to 1)";
    return read;
}

Result<Image> readImage(const std::string& path, const ImageReadOptions& options) {
    // Opened first without blocking: a FIFO or a device is refused by name, never waited on, and
    // the file is recorded as an input of the run (Inputs.h) before anything reads it.
    Result<InputFile> file = InputFile::open(path);
    if (!file)
        return file.error();
    if (file->size() == 0)
        return fileError(path, "the file is empty (0 bytes)");
    // Before OpenEXR, which allocates what a damaged header claims (fuzzing found 1.7 GB).
    if (Status exr = checkExrHeader(path); !exr)
        return exr.error();
    if (Status png = checkPngStructure(path); !png)
        return png.error();

    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1); // material maps are not premultiplied
    auto input = OIIO::ImageInput::open(path, &config);
    if (!input)
        return fileError(path, "not a readable image (" + oiioMessage(OIIO::geterror()) + ")");

    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        return fileError(path, "the image has zero size");
    if (spec.depth > 1)
        return fileError(path, "volume images are not supported");
    if (spec.width > options.maxSide || spec.height > options.maxSide)
        return fileError(path, "the image is " + std::to_string(spec.width) + "x" +
                                   std::to_string(spec.height) + ", larger than the limit of " +
                                   std::to_string(options.maxSide) + " texels a side");

    // Bits as stored: the channels' own formats (EXR mixes half and float), or fewer than 8 bits
    // a sample where the format says so.
    std::int64_t bitsPerTexel = 0;
    for (int c = 0; c < spec.nchannels; ++c)
        bitsPerTexel += static_cast<std::int64_t>(spec.channelformat(c).size()) * 8;
    if (const int bits = spec.get_int_attribute("oiio:BitsPerSample"); bits > 0)
        bitsPerTexel = static_cast<std::int64_t>(bits) * spec.nchannels;
    ImageClaim claim{spec.width,
                     spec.height,
                     spec.nchannels,
                     bitsPerTexel,
                     input->format_name(),
                     spec.get_string_attribute("compression"),
                     static_cast<std::int64_t>(file->size())};
    if (Status fits = checkImageClaim(path, claim); !fits)
        return fits.error();
    if (Status data = checkPngData(path); !data)
        return data.error();

    try {
        Image image(spec.width, spec.height, spec.nchannels);
        if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
            return fileError(path, "the image data could not be read, the file may be truncated (" +
                                       oiioMessage(input->geterror()) + ")");
        input->close();
        image.alphaOnly = spec.nchannels == 1 && spec.alpha_channel == 0;
        if (options.rejectNonFinite) {
            if (Status finite = checkFinite(path, image); !finite)
                return finite.error();
        }
        if (Status s = checkMagnitude(path, image, options.maxMagnitude, options.limitReason); !s)
            return s.error();
        return image;
    } catch (const std::bad_alloc&) {
        return fileError(path, "not enough memory to read the " + std::to_string(spec.width) + "x" +
                                   std::to_string(spec.height) + " image");
    }
}

Result<PixelFormat> pixelFormatFromBits(int bits) {
    switch (bits) {
    case 8:
        return PixelFormat::UInt8;
    case 16:
        return PixelFormat::UInt16;
    case 32:
        return PixelFormat::Float;
    default:
        return Error{"bit depth " + std::to_string(bits) + " is not one of 8, 16, 32 (float)"};
    }
}

bool extensionSupports(const std::string& path, PixelFormat format) {
    const std::string ext = lowerExtension(path);
    if (ext == ".png")
        return format == PixelFormat::UInt8 || format == PixelFormat::UInt16;
    if (ext == ".exr")
        return format == PixelFormat::Half || format == PixelFormat::Float;
    if (ext == ".tif" || ext == ".tiff")
        return true;
    if (ext == ".bmp" || ext == ".jpg" || ext == ".jpeg" || ext == ".tga")
        return format == PixelFormat::UInt8;
    return false;
}

Status writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options) {
    if (image.empty())
        return fileError(path, "refusing to write an empty image");
    if (!extensionSupports(path, options.format))
        return fileError(path, "this file type cannot store the requested pixel format "
                               "(PNG: 8/16-bit, EXR: half/float, TIFF: any)");

    auto output = OIIO::ImageOutput::create(path);
    if (!output)
        return fileError(path, "no image writer for this extension");

    OIIO::ImageSpec spec(image.width, image.height, image.channels, typeOf(options.format));
    spec.attribute("oiio:UnassociatedAlpha", 1);
    // A PNG tagged "Linear" gets a gAMA 1.0 chunk, which Godot's and Unity's loaders apply: a
    // flat normal's 0.498 would read as 0.729. Untagged, every loader takes the values as stored.
    if (options.srgb)
        spec.attribute("oiio:ColorSpace", "sRGB");
    else if (lowerExtension(path) != ".png")
        spec.attribute("oiio:ColorSpace", "Linear");
    if (lowerExtension(path) == ".exr")
        spec.attribute("compression", "zip");

    // Encoded in memory, then written with every step checked (writeFileAtomically): the image
    // writers do not all report a full disk.
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    if (!output->supports("ioproxy") || !output->set_ioproxy(&memory))
        return fileError(path, "this file type cannot be encoded in memory");
    if (!output->open(path, spec))
        return fileError(path, "cannot encode the image (" + oiioMessage(output->geterror()) + ")");
    const bool written = output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    const bool closed = output->close();
    if (!written || !closed)
        return fileError(path, "encoding failed (" + oiioMessage(output->geterror()) + ")");
    return writeFileAtomically(
        path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

} // namespace px

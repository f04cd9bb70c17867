#include "parallax/image/ImageFile.h"

#include "ExrHeaderCheck.h"
#include "FileSizeBound.h"
#include "ImageBudget.h"
#include "ImageFormat.h"
#include "ImageModule.h"
#include "JpegCheck.h"
#include "Orientation.h"
#include "PngCheck.h"
#include "PngCodec.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/FileExtension.h"
#include "parallax/io/Inputs.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <new>
#include <string_view>

namespace px {
namespace {

// PNG by the core's own codec, anything else by the OpenImageIO module (loaded now if not yet);
// both from the bytes read once through the input's descriptor, the format as their signature
// says, damage the format's own structure shows found first.
Result<std::unique_ptr<ImageDecoder>> openDecoder(const ImageSource& source) {
    const std::string& path = source.path;
    const std::string& bytes = *source.bytes;
    if (source.format == "png") {
        if (Status png = checkPngStructure(path, bytes); !png)
            return png.error();
        if (source.page > 0 || !source.layer.empty())
            return fileError(path, "a PNG holds one image, with no pages or layers to choose");
        Result<std::unique_ptr<ImageDecoder>> decoder = openPng(source.bytes);
        if (!decoder)
            return fileError(path, decoder.error().message);
        return decoder;
    }
    if (source.format == "jpeg") {
        if (Status jpeg = checkJpegStructure(path, bytes); !jpeg)
            return jpeg.error();
    }
    // Before OpenEXR, which allocates what a damaged header claims (fuzzing found 1.7 GB).
    if (source.format == "openexr") {
        if (Status exr = checkExrHeader(path, bytes); !exr)
            return exr.error();
    }
    Result<const ImageModule*> module = imageModule();
    if (!module)
        return fileError(path, module.error().message);
    Result<std::unique_ptr<ImageDecoder>> decoder = (*module)->open(source);
    if (!decoder)
        return fileError(path, decoder.error().message);
    return decoder;
}

void printNote(const std::string& note) {
    std::fprintf(stderr, "note: %s\n", note.c_str());
}

std::atomic<ImageNoteSink> g_noteSink{printNote};

Result<std::vector<unsigned char>> encodeFor(const std::string& path, const Image& image,
                                             const ImageWriteOptions& options) {
    if (lowerExtension(path) == ".png")
        return encodePng(image, options.format, options.srgb);
    Result<const ImageModule*> module = imageModule();
    if (!module)
        return module.error();
    return (*module)->encode(path, image, options);
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

void setImageNoteSink(ImageNoteSink sink) {
    g_noteSink = sink ? sink : printNote;
}

Result<Image> readImage(const std::string& path, const ImageReadOptions& options) {
    // Opened first without blocking: a FIFO or a device is refused by name, never waited on, and
    // the file is recorded as an input of the run (Inputs.h); then read once, whole, through that
    // descriptor: no decoder opens the path again.
    Result<InputFile> file = InputFile::open(path);
    if (!file)
        return file.error();
    if (file->size() == 0)
        return fileError(path, "the file is empty (0 bytes)");
    Result<std::string> content = file->readAll(file->size());
    if (!content)
        return content.error();
    ImageSource source;
    source.path = path;
    source.bytes = std::make_shared<const std::string>(std::move(*content));
    source.format = imageFormatOf(*source.bytes, path);
    source.layer = options.layer;
    source.page = options.page;
    if (source.format.empty())
        return fileError(path, "not a readable image (its first bytes are the signature of no "
                               "format this tool reads: PNG, JPEG, TIFF, OpenEXR, Radiance HDR, "
                               "BMP, Targa, PNM, SGI, DDS, PSD, GIF, WebP and the others in "
                               "docs/image-files.md)");

    // Formats whose header the core reads itself are bounded before any decoder opens them.
    const std::int64_t fileBytes = static_cast<std::int64_t>(source.bytes->size());
    const std::optional<StoredClaim> early = claimInHeader(*source.bytes, source.format);
    if (early) {
        if (Status fits =
                checkImageClaim(path, {early->width, early->height, 1, early->minBytes, fileBytes});
            !fits)
            return fits.error();
    }

    Result<std::unique_ptr<ImageDecoder>> decoder = openDecoder(source);
    if (!decoder)
        return decoder.error();
    const ImageHeader header = (*decoder)->header(); // a copy: the decoder goes before the checks
    if (header.width <= 0 || header.height <= 0 || header.channels <= 0)
        return fileError(path, "the image has zero size");
    if (header.depth > 1)
        return fileError(path, "volume images are not supported");
    if (header.width > options.maxSide || header.height > options.maxSide)
        return fileError(path, "the image is " + std::to_string(header.width) + "x" +
                                   std::to_string(header.height) + ", larger than the limit of " +
                                   std::to_string(options.maxSide) + " texels a side");
    const ImageClaim claim{header.width, header.height, header.channels,
                           early ? early->minBytes : minFileBytes(header), fileBytes};
    if (Status fits = checkImageClaim(path, claim); !fits)
        return fits.error();

    try {
        Image image(header.width, header.height, header.channels);
        if (Status read = (*decoder)->read(image.pixels.data()); !read)
            return fileError(path, read.error().message);
        decoder->reset(); // its copy of the file's bytes too
        source.bytes.reset();
        image.alphaOnly = header.alphaOnly;
        std::string note;
        if (header.orientation > 1) {
            image = upright(image, header.orientation);
            note = path + ": " + orientationChange(header.orientation) + " to be upright, as " +
                   (header.format == "hdr"
                        ? "its resolution line (+Y, stored bottom-up)"
                        : "its Orientation tag (" + std::to_string(header.orientation) + ")") +
                   " says";
        }
        if (!header.chosen.empty())
            note += (note.empty() ? path + ": read " : "; read ") + header.chosen;
        if (options.rejectNonFinite) {
            if (Status finite = checkFinite(path, image); !finite)
                return finite.error();
        }
        if (Status s = checkMagnitude(path, image, options.maxMagnitude, options.limitReason); !s)
            return s.error();
        if (!note.empty())
            g_noteSink.load()(note);
        return image;
    } catch (const std::bad_alloc&) {
        return fileError(path, "not enough memory to read the " + std::to_string(header.width) +
                                   "x" + std::to_string(header.height) + " image");
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

    // Encoded in memory, then written with every step checked (writeFileAtomically): the image
    // writers do not all report a full disk.
    Result<std::vector<unsigned char>> encoded = encodeFor(path, image, options);
    if (!encoded)
        return fileError(path, encoded.error().message);
    return writeFileAtomically(
        path, std::string_view(reinterpret_cast<const char*>(encoded->data()), encoded->size()));
}

} // namespace px

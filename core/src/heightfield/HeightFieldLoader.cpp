#include "parallax/heightfield/HeightFieldLoader.h"

#include "parallax/image/ImageFile.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace px {

std::optional<HeightChannel> parseHeightChannel(std::string_view name) {
    if (name == "red" || name == "r")
        return HeightChannel::Red;
    if (name == "green" || name == "g")
        return HeightChannel::Green;
    if (name == "blue" || name == "b")
        return HeightChannel::Blue;
    if (name == "alpha" || name == "a")
        return HeightChannel::Alpha;
    if (name == "luminance" || name == "luma")
        return HeightChannel::Luminance;
    return std::nullopt;
}

namespace {

// Rec. 709 luma of the (linear) channel values.
float luminance(const Image& image, int x, int y) {
    return 0.2126f * image.at(x, y, 0) + 0.7152f * image.at(x, y, 1) + 0.0722f * image.at(x, y, 2);
}

std::string rangeText(float lo, float hi) {
    std::ostringstream text;
    text << "[" << lo << ", " << hi << "]";
    return text.str();
}

} // namespace

Result<HeightField> heightFieldFromImage(Image image, const HeightLoadOptions& options,
                                         const std::string& source) {
    if (image.empty())
        return fileError(source, "the image has zero size");
    const int n = image.channels;
    int channel = 0;
    bool luma = false;
    switch (options.channel) {
    case HeightChannel::Red:
        channel = 0;
        break;
    case HeightChannel::Green:
        channel = 1;
        break;
    case HeightChannel::Blue:
        channel = 2;
        break;
    case HeightChannel::Alpha:
        channel = (n == 2 || n == 4) ? n - 1 : -1;
        break;
    case HeightChannel::Luminance:
        luma = n >= 3;
        channel = 0; // a grey image is its own luminance
        break;
    }
    // An EXR holding only "A": reading it as red would take the alpha without a word.
    if (image.alphaOnly) {
        if (options.channel != HeightChannel::Alpha)
            return fileError(source, "the image's only channel is alpha (A): say --channel alpha "
                                     "to read the height from it");
        channel = 0;
    }
    if (channel < 0 || channel >= n)
        return fileError(source, "the requested channel does not exist (the image has " +
                                     std::to_string(n) + " channel" + (n == 1 ? "" : "s") + ")");

    HeightField field;
    if (n == 1) {
        // A grey image's texels are the field's: shared, not copied (an 8192² map is 256 MB).
        field.width = image.width;
        field.height = image.height;
        field.texels = std::move(image.pixels);
    } else {
        field = HeightField(image.width, image.height);
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x)
                field.at(x, y) = luma ? luminance(image, x, y) : image.at(x, y, channel);
        }
    }

    const float lo = field.minHeight();
    const float hi = field.maxHeight();
    if (options.normalize) {
        const float span = hi - lo;
        for (float& h : field.texels)
            h = span > 0.0f ? (h - lo) / span : 0.0f;
    } else if (lo < 0.0f || hi > 1.0f) {
        return fileError(source, "height values span " + rangeText(lo, hi) +
                                     ", outside [0, 1]; remap it to [0, 1] with --normalize");
    }
    if (options.invert) {
        for (float& h : field.texels)
            h = 1.0f - h;
    }
    return field;
}

Result<HeightField> loadHeightField(const std::string& path, const HeightLoadOptions& options) {
    ImageReadOptions read;
    read.maxSide = options.allowLarge ? (1 << 30) : 16384;
    Result<Image> image = readImage(path, read);
    if (!image)
        return image.error();
    return heightFieldFromImage(std::move(*image), options, path);
}

} // namespace px

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

std::string valueText(float value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string rangeText(float lo, float hi) {
    return "[" + valueText(lo) + ", " + valueText(hi) + "]";
}

} // namespace

namespace {

// The requested channel of `image` as a field, values as stored.
Result<HeightField> extractChannel(Image image, const HeightLoadOptions& options,
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
        const PlaneWriter put = field.writer();
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x)
                put.at(x, y) =
                    luma ? luminance(image, x, y) : std::as_const(image).at(x, y, channel);
        }
    }
    return field;
}

// h = (value - lo) / (hi - lo), in double so that lo and hi land on 0 and 1 exactly.
void applyRange(HeightField& field, HeightRange range) {
    const double lo = range.lo, span = static_cast<double>(range.hi) - lo;
    for (float& h : field.texels)
        h = static_cast<float>((h - lo) / span);
}

void invert(HeightField& field) {
    for (float& h : field.texels)
        h = 1.0f - h;
}

bool within(float lo, float hi, HeightRange range) {
    return lo >= range.lo && hi <= range.hi;
}

} // namespace

Result<HeightField> heightFieldFromImage(Image image, const HeightLoadOptions& options,
                                         const std::string& source) {
    Result<HeightField> extracted = extractChannel(std::move(image), options, source);
    if (!extracted)
        return extracted.error();
    HeightField field = std::move(*extracted);
    const float lo = field.minHeight();
    const float hi = field.maxHeight();
    if (options.range) {
        if (!within(lo, hi, *options.range))
            return fileError(source, "height values span " + rangeText(lo, hi) +
                                         ", outside the material's height range " +
                                         rangeText(options.range->lo, options.range->hi) +
                                         ": it is not the file the range was recorded from; "
                                         "import it again, or correct /height/range");
        applyRange(field, *options.range);
    }
    if (options.normalize) {
        const float a = field.minHeight(), b = field.maxHeight();
        const float span = b - a;
        for (float& h : field.texels)
            h = span > 0.0f ? (h - a) / span : 0.0f;
    } else if (!options.range && (lo < 0.0f || hi > 1.0f)) {
        return fileError(source, "height values span " + rangeText(lo, hi) +
                                     ", outside [0, 1]: give the material the file's range "
                                     "(\"height\": {\"range\": [lo, hi]}; import does), or "
                                     "remap it to [0, 1] with --normalize");
    }
    if (options.invert)
        invert(field);
    return field;
}

Result<FittedHeight> fitHeightField(Image image, const HeightLoadOptions& options,
                                    const std::string& source) {
    Result<HeightField> extracted = extractChannel(std::move(image), options, source);
    if (!extracted)
        return extracted.error();
    FittedHeight out;
    out.field = std::move(*extracted);
    const float lo = out.field.minHeight();
    const float hi = out.field.maxHeight();
    if (options.range && within(lo, hi, *options.range)) {
        out.range = options.range; // the material's own, still right for the file
    } else if (!within(lo, hi, HeightRange{})) {
        if (!(hi > lo))
            return fileError(source, "every height texel holds " + valueText(lo) +
                                         ", outside [0, 1]: one value gives no range to read a "
                                         "relief by");
        out.range = HeightRange{lo, hi};
    }
    if (out.range)
        applyRange(out.field, *out.range);
    if (options.invert)
        invert(out.field);
    return out;
}

Result<HeightField> loadHeightField(const std::string& path, const HeightLoadOptions& options) {
    ImageReadOptions read;
    read.maxSide = options.allowLarge ? (1 << 30) : 16384;
    read.layer = options.layer;
    read.page = options.page;
    Result<Image> image = readImage(path, read);
    if (!image)
        return image.error();
    return heightFieldFromImage(std::move(*image), options, path);
}

Result<FittedHeight> loadHeightFieldFitted(const std::string& path,
                                           const HeightLoadOptions& options) {
    ImageReadOptions read;
    read.maxSide = options.allowLarge ? (1 << 30) : 16384;
    read.layer = options.layer;
    read.page = options.page;
    Result<Image> image = readImage(path, read);
    if (!image)
        return image.error();
    return fitHeightField(std::move(*image), options, path);
}

} // namespace px

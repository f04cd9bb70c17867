#include "PngCodec.h"

#include "PngDeflate.h"

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <png.h>

namespace px {
namespace {

// libpng reports an error by calling this and expects it not to return: the message is kept and
// control goes back to the setjmp of the call that failed. Warnings are dropped (libpng reads on).
void keepError(png_structp png, png_const_charp message) {
    *static_cast<std::string*>(png_get_error_ptr(png)) = message ? message : "";
    png_longjmp(png, 1);
}

void dropWarning(png_structp, png_const_charp) {}

// libpng's reads, from the file's bytes in memory; past the end is libpng's error.
struct MemorySource {
    std::shared_ptr<const std::string> bytes;
    std::size_t at = 0;
};

void readBytes(png_structp png, png_bytep out, png_size_t size) {
    auto* source = static_cast<MemorySource*>(png_get_io_ptr(png));
    if (size > source->bytes->size() - source->at)
        png_error(png, "the data ends early");
    std::copy_n(source->bytes->data() + source->at, size, out);
    source->at += size;
}

int storedChannels(int colour) {
    switch (colour) {
    case PNG_COLOR_TYPE_GRAY_ALPHA:
        return 2;
    case PNG_COLOR_TYPE_RGB:
        return 3;
    case PNG_COLOR_TYPE_RGB_ALPHA:
        return 4;
    default: // grey, palette
        return 1;
    }
}

class PngDecoder final : public ImageDecoder {
public:
    explicit PngDecoder(std::shared_ptr<const std::string> bytes) : m_source{std::move(bytes), 0} {}
    ~PngDecoder() override { png_destroy_read_struct(&m_png, &m_info, nullptr); }

    // False with m_message on libpng's error (no locals between setjmp and longjmp).
    bool readInfo() {
        m_png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &m_message, keepError, dropWarning);
        m_info = m_png ? png_create_info_struct(m_png) : nullptr;
        if (!m_info) {
            m_message = "not enough memory to read the PNG";
            return false;
        }
        if (setjmp(png_jmpbuf(m_png)) != 0)
            return false;
        png_set_read_fn(m_png, &m_source, readBytes);
        png_read_info(m_png, m_info);
        const int stored = png_get_bit_depth(m_png, m_info);
        const int colour = png_get_color_type(m_png, m_info);
        if (colour == PNG_COLOR_TYPE_PALETTE)
            png_set_palette_to_rgb(m_png);
        if (colour == PNG_COLOR_TYPE_GRAY && stored < 8)
            png_set_expand_gray_1_2_4_to_8(m_png);
        if (png_get_valid(m_png, m_info, PNG_INFO_tRNS) != 0)
            png_set_tRNS_to_alpha(m_png);
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
        if (stored == 16)
            png_set_swap(m_png); // big-endian in the file, native in memory
#endif
        m_passes = png_set_interlace_handling(m_png);
        png_read_update_info(m_png, m_info);
        m_header.width = static_cast<int>(png_get_image_width(m_png, m_info));
        m_header.height = static_cast<int>(png_get_image_height(m_png, m_info));
        m_header.channels = png_get_channels(m_png, m_info);
        // As stored, before expansion: a palette texel is one index of `stored` bits, whatever
        // its colours and tRNS expand to.
        m_header.bitsPerTexel = static_cast<std::int64_t>(stored) * storedChannels(colour);
        m_header.format = "png";
        m_bits = png_get_bit_depth(m_png, m_info);
        return true;
    }

    const std::string& message() const {
        return m_message;
    }
    const ImageHeader& header() const override {
        return m_header;
    }

    Status read(float* texels) override {
        const std::size_t rowValues = static_cast<std::size_t>(m_header.width) * m_header.channels;
        // An interlaced image is built up over seven passes in the whole image's rows; otherwise
        // one row at a time, each converted as it arrives.
        const std::size_t rows = m_passes > 1 ? static_cast<std::size_t>(m_header.height) : 1;
        m_rows.assign(rows * png_get_rowbytes(m_png, m_info), 0);
        m_out = texels;
        if (!decode())
            return Error{"the file is damaged (its image data does not decode: " + m_message + ")"};
        if (m_passes > 1)
            for (int y = 0; y < m_header.height; ++y)
                convert(m_rows.data() + y * png_get_rowbytes(m_png, m_info), rowValues,
                        texels + y * rowValues);
        return success();
    }

private:
    // Every row of every pass; false with m_message on libpng's error.
    bool decode() {
        if (setjmp(png_jmpbuf(m_png)) != 0)
            return false;
        const std::size_t rowBytes = png_get_rowbytes(m_png, m_info);
        const std::size_t rowValues = static_cast<std::size_t>(m_header.width) * m_header.channels;
        for (int pass = 0; pass < m_passes; ++pass) {
            for (int y = 0; y < m_header.height; ++y) {
                png_bytep row = m_rows.data() + (m_passes > 1 ? y * rowBytes : 0);
                png_read_row(m_png, row, nullptr);
                if (m_passes == 1)
                    convert(row, rowValues, m_out + y * rowValues);
            }
        }
        png_read_end(m_png, nullptr);
        return true;
    }

    void convert(const png_byte* row, std::size_t count, float* out) const {
        // As OpenImageIO converts: the integer times the reciprocal of its largest value.
        if (m_bits == 16) {
            const auto* values = reinterpret_cast<const std::uint16_t*>(row);
            for (std::size_t i = 0; i < count; ++i)
                out[i] = static_cast<float>(values[i]) * (1.0f / 65535.0f);
        } else {
            for (std::size_t i = 0; i < count; ++i)
                out[i] = static_cast<float>(row[i]) * (1.0f / 255.0f);
        }
    }

    MemorySource m_source;
    png_structp m_png = nullptr;
    png_infop m_info = nullptr;
    std::string m_message;
    ImageHeader m_header;
    int m_passes = 1;
    int m_bits = 8;
    std::vector<png_byte> m_rows;
    float* m_out = nullptr;
};

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}

void flushNothing(png_structp) {}

// Round to nearest, half up, on the exact value: in double, where v * 65535 + 0.5 is exact. (In
// float, v * 255 + 0.5 rounds 0.49999997 up to 1; OpenImageIO's own writer does that in some
// positions of a row and not in others.)
template <typename T> T quantised(float value, double top) {
    const double clamped = value > 0.0f ? std::min(static_cast<double>(value), 1.0) : 0.0; // NaN: 0
    return static_cast<T>(std::floor(clamped * top + 0.5));
}

struct PngEncode {
    std::string message;
    std::vector<unsigned char> bytes;
};

// zlib's level for the image data, chosen by measurement (docs/platform.md): on a 2048² 16-bit
// cone map 5 takes 2.2x less CPU than libpng's default 6 for a file 1.3% larger.
constexpr int kPngLevel = 5;

// The signature, IHDR and colour chunks into encode.bytes; false with encode.message on libpng's
// error.
bool encodeHeader(png_structp png, png_infop info, const Image& image, bool sixteen, bool srgb,
                  PngEncode& encode) {
    if (setjmp(png_jmpbuf(png)) != 0)
        return false;
    static constexpr int kColour[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                      PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    png_set_write_fn(png, &encode.bytes, appendBytes, flushNothing);
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
                 static_cast<png_uint_32>(image.height), sixteen ? 16 : 8,
                 kColour[image.channels - 1], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (srgb)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
    png_write_info(png, info);
    return true;
}

} // namespace

Result<std::unique_ptr<ImageDecoder>> openPng(std::shared_ptr<const std::string> bytes) {
    auto decoder = std::make_unique<PngDecoder>(std::move(bytes));
    if (!decoder->readInfo())
        return Error{"not a readable image (" + decoder->message() + ")"};
    return std::unique_ptr<ImageDecoder>(std::move(decoder));
}

Result<std::vector<unsigned char>> encodePng(const Image& image, PixelFormat format, bool srgb) {
    if (image.channels < 1 || image.channels > 4)
        return Error{"a PNG holds 1 to 4 channels, not " + std::to_string(image.channels)};
    if (format != PixelFormat::UInt8 && format != PixelFormat::UInt16)
        return Error{"a PNG holds 8 or 16 bits a channel"};
    PngEncode encode;
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &encode.message, keepError, dropWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return Error{"not enough memory to encode the PNG"};
    }
    const bool sixteen = format == PixelFormat::UInt16;
    const bool encoded = encodeHeader(png, info, image, sixteen, srgb, encode);
    png_destroy_write_struct(&png, &info);
    if (!encoded)
        return Error{"encoding failed (" + encode.message + ")"};
    // The image data and IEND: rows filtered and deflated on every core (PngDeflate.h), not
    // libpng's one thread.
    const std::size_t values = static_cast<std::size_t>(image.width) * image.channels;
    PngRows rows;
    rows.width = image.width;
    rows.height = image.height;
    rows.bytesPerTexel = image.channels * (sixteen ? 2 : 1);
    const float* texels = image.pixels.data();
    rows.row = [&](int y, std::uint8_t* out) {
        const float* source = texels + static_cast<std::size_t>(y) * values;
        for (std::size_t i = 0; i < values; ++i) {
            if (sixteen) {
                const auto v = quantised<std::uint16_t>(source[i], 65535.0);
                out[2 * i] = static_cast<std::uint8_t>(v >> 8); // big-endian in the file
                out[2 * i + 1] = static_cast<std::uint8_t>(v & 0xff);
            } else {
                out[i] = quantised<png_byte>(source[i], 255.0);
            }
        }
    };
    if (!appendPngImageData(rows, kPngLevel, encode.bytes))
        return Error{"encoding failed (not enough memory to compress the image)"};
    return std::move(encode.bytes);
}

} // namespace px

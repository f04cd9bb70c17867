#include "PngCheck.h"

#include <array>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <png.h>
#include <string>
#include <vector>

namespace px {

namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t crc32(const unsigned char* data, std::size_t size) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k)
                c = (c & 1u) != 0 ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i)
        crc = table[(crc ^ data[i]) & 0xffu] ^ (crc >> 8);
    return ~crc;
}

std::uint32_t big32(const unsigned char* p) {
    return static_cast<std::uint32_t>(p[0]) << 24 | static_cast<std::uint32_t>(p[1]) << 16 |
           static_cast<std::uint32_t>(p[2]) << 8 | static_cast<std::uint32_t>(p[3]);
}

// libpng reports an error by calling this and expects it not to return: the message is kept and
// control goes back to the setjmp in decodeRows. Warnings are dropped (OpenImageIO reads on).
void keepError(png_structp png, png_const_charp message) {
    *static_cast<std::string*>(png_get_error_ptr(png)) = message ? message : "";
    png_longjmp(png, 1);
}

void dropWarning(png_structp, png_const_charp) {}

// What a decode keeps outside the frame that calls setjmp, so that nothing there changes between
// the setjmp and a longjmp back to it.
struct PngDecode {
    std::string message;
    std::vector<png_byte> row;
};

// Reads every row of every pass into one row buffer; false with decode.message on libpng's error.
bool decodeRows(png_structp png, png_infop info, PngDecode& decode) {
    if (setjmp(png_jmpbuf(png)) != 0)
        return false;
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    decode.row.resize(png_get_rowbytes(png, info));
    const png_uint_32 height = png_get_image_height(png, info);
    for (int pass = 0; pass < passes; ++pass)
        for (png_uint_32 y = 0; y < height; ++y)
            png_read_row(png, decode.row.data(), nullptr);
    png_read_end(png, nullptr);
    return true;
}

} // namespace

Status checkPngStructure(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, data))
        return success();
    std::size_t at = 8;
    while (at + 12 <= bytes.size()) {
        const std::uint32_t length = big32(data + at);
        const std::string type = bytes.substr(at + 4, 4);
        if (length > bytes.size() - at - 12)
            return fileError(path, "the file is truncated (its " + type +
                                       " chunk runs past the end, "
                                       "at byte " +
                                       std::to_string(bytes.size()) + ")");
        if (crc32(data + at + 4, length + 4) != big32(data + at + 8 + length))
            return fileError(path, "the file is damaged (its " + type +
                                       " chunk does not match its checksum)");
        if (type == "IEND")
            return success();
        at += 12 + length;
    }
    return fileError(path, "the file is truncated (it ends at byte " +
                               std::to_string(bytes.size()) + " without the PNG's IEND chunk)");
}

Status checkPngData(const std::string& path) {
    const std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    unsigned char signature[8] = {};
    if (!file || std::fread(signature, 1, 8, file.get()) != 8 ||
        !std::equal(kSignature, kSignature + 8, signature))
        return success();
    PngDecode decode;
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &decode.message, keepError, dropWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return fileError(path, "not enough memory to check the PNG");
    }
    png_init_io(png, file.get());
    const bool decoded = decodeRows(png, info, decode);
    png_destroy_read_struct(&png, &info, nullptr);
    if (!decoded)
        return fileError(
            path, "the file is damaged (its image data does not decode: " + decode.message + ")");
    return success();
}

} // namespace px

#include "ImageFormat.h"

#include "parallax/io/FileExtension.h"

#include <array>

namespace px {
namespace {

struct Signature {
    std::size_t offset;
    std::string_view bytes;
    const char* format;
};

using namespace std::string_view_literals;

// First match wins; longer and more specific signatures first.
constexpr std::array kSignatures = {
    Signature{0, "\x89PNG\r\n\x1a\n"sv, "png"},
    Signature{0, "\xff\xd8\xff"sv, "jpeg"},
    Signature{0, "II*\0"sv, "tiff"},
    Signature{0, "MM\0*"sv, "tiff"},
    Signature{0, "II+\0"sv, "tiff"}, // BigTIFF
    Signature{0, "MM\0+"sv, "tiff"},
    Signature{0, "\x76\x2f\x31\x01"sv, "openexr"},
    Signature{0, "#?RADIANCE"sv, "hdr"},
    Signature{0, "#?RGBE"sv, "hdr"},
    Signature{0, "DDS "sv, "dds"},
    Signature{0, "8BPS"sv, "psd"},
    Signature{0, "GIF87a"sv, "gif"},
    Signature{0, "GIF89a"sv, "gif"},
    Signature{8, "WEBP"sv, "webp"},
    Signature{0, "\x01\xda"sv, "sgi"},
    Signature{0, "\0\0\1\0"sv, "ico"},
    Signature{0, "\xff\x4f\xff\x51"sv, "jpeg2000"},
    Signature{0, "\0\0\0\x0cjP  "sv, "jpeg2000"},
    Signature{4, "ftypheic"sv, "heif"},
    Signature{4, "ftypheix"sv, "heif"},
    Signature{4, "ftypmif1"sv, "heif"},
    Signature{4, "ftypavif"sv, "heif"},
    Signature{0, "SDPX"sv, "dpx"},
    Signature{0, "XPDS"sv, "dpx"},
    Signature{0, "\x80\x2a\x5f\xd7"sv, "cineon"},
    Signature{0, "SIMPLE  ="sv, "fits"},
    Signature{0, "FORM"sv, "iff"},
    Signature{0, "BM"sv, "bmp"},
};

bool isPnm(std::string_view bytes) {
    if (bytes.size() < 3 || bytes[0] != 'P')
        return false;
    const char kind = bytes[1];
    const bool known = (kind >= '1' && kind <= '6') || kind == 'F' || kind == 'f';
    const char next = bytes[2];
    return known && (next == ' ' || next == '\t' || next == '\n' || next == '\r' || next == '#');
}

} // namespace

std::string imageFormatOf(std::string_view bytes, const std::string& path) {
    for (const Signature& s : kSignatures) {
        if (bytes.size() >= s.offset + s.bytes.size() &&
            bytes.substr(s.offset, s.bytes.size()) == s.bytes) {
            if (std::string_view(s.format) == "webp" && bytes.substr(0, 4) != "RIFF")
                continue;
            return s.format;
        }
    }
    if (isPnm(bytes))
        return "pnm";
    const std::string ext = lowerExtension(path);
    if (ext == ".tga" || ext == ".tpic" || ext == ".icb" || ext == ".vda" || ext == ".vst")
        return "targa";
    return {};
}

} // namespace px

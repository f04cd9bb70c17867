#include "PngCheck.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <zlib.h>

namespace px {

namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t big32(const unsigned char* p) {
    return static_cast<std::uint32_t>(p[0]) << 24 | static_cast<std::uint32_t>(p[1]) << 16 |
           static_cast<std::uint32_t>(p[2]) << 8 | static_cast<std::uint32_t>(p[3]);
}

} // namespace

bool hasPngSignature(std::string_view bytes) {
    return bytes.size() >= 8 && std::equal(kSignature, kSignature + 8,
                                           reinterpret_cast<const unsigned char*>(bytes.data()));
}

Status checkPngStructure(const std::string& path, std::string_view bytes) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t at = 8;
    while (at + 12 <= bytes.size()) {
        const std::uint32_t length = big32(data + at);
        const std::string type(bytes.substr(at + 4, 4));
        if (length > bytes.size() - at - 12)
            return fileError(path, "the file is truncated (its " + type +
                                       " chunk runs past the end, "
                                       "at byte " +
                                       std::to_string(bytes.size()) + ")");
        if (::crc32(0, data + at + 4, length + 4) != big32(data + at + 8 + length))
            return fileError(path, "the file is damaged (its " + type +
                                       " chunk does not match its checksum)");
        if (type == "IEND")
            return success();
        at += 12 + length;
    }
    return fileError(path, "the file is truncated (it ends at byte " +
                               std::to_string(bytes.size()) + " without the PNG's IEND chunk)");
}

} // namespace px

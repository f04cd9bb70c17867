#include "ExrHeaderCheck.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <optional>

namespace px {
namespace {

constexpr std::array<unsigned char, 4> kExrMagic = {0x76, 0x2f, 0x31, 0x01};
constexpr std::uint32_t kMultiPartFlag = 0x1000;
constexpr int kMaxNameLength = 255; // with the long-names flag; shorter names are a subset

class HeaderReader {
public:
    HeaderReader(std::ifstream& in, std::int64_t fileSize) : in_(in), fileSize_(fileSize) {}

    std::int64_t remaining() { return fileSize_ - static_cast<std::int64_t>(in_.tellg()); }

    // A NUL-terminated string; nullopt at end of file or when no NUL comes within the limit.
    std::optional<std::string> string() {
        std::string text;
        for (int i = 0; i <= kMaxNameLength; ++i) {
            const int c = in_.get();
            if (c == std::char_traits<char>::eof())
                return std::nullopt;
            if (c == 0)
                return text;
            text.push_back(static_cast<char>(c));
        }
        return std::nullopt;
    }

    std::optional<std::int32_t> int32() {
        std::array<unsigned char, 4> bytes{};
        if (!in_.read(reinterpret_cast<char*>(bytes.data()), bytes.size()))
            return std::nullopt;
        const std::uint32_t value = bytes[0] | (bytes[1] << 8U) | (bytes[2] << 16U) |
                                    (static_cast<std::uint32_t>(bytes[3]) << 24U);
        return static_cast<std::int32_t>(value);
    }

    void skip(std::int32_t bytes) { in_.seekg(bytes, std::ios::cur); }

private:
    std::ifstream& in_;
    std::int64_t fileSize_;
};

// One header: attributes until an empty name. Returns false (with the error) on a bad one and sets
// `empty` when the header had no attribute at all (the end of a multi-part header list).
Status checkOneHeader(const std::string& path, HeaderReader& reader, bool& empty) {
    empty = true;
    for (;;) {
        const std::optional<std::string> name = reader.string();
        if (!name)
            return fileError(path, "the OpenEXR header is truncated or has an unterminated "
                                   "attribute name");
        if (name->empty())
            return success();
        empty = false;
        const std::optional<std::string> type = reader.string();
        const std::optional<std::int32_t> size = type ? reader.int32() : std::nullopt;
        if (!size)
            return fileError(path, "the OpenEXR header is truncated in attribute '" + *name + "'");
        const std::int64_t left = reader.remaining();
        if (*size < 0 || *size > left)
            return fileError(path, "the OpenEXR header attribute '" + *name + "' claims " +
                                       std::to_string(*size) + " bytes but only " +
                                       std::to_string(left) +
                                       " remain in the file (the file is damaged)");
        reader.skip(*size);
    }
}

} // namespace

Status checkExrHeader(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        return success(); // unreadable files get OpenImageIO's own message
    const std::int64_t fileSize = static_cast<std::int64_t>(in.tellg());
    in.seekg(0);
    std::array<unsigned char, 4> magic{};
    if (!in.read(reinterpret_cast<char*>(magic.data()), magic.size()) || magic != kExrMagic)
        return success();
    HeaderReader reader(in, fileSize);
    const std::optional<std::int32_t> version = reader.int32();
    if (!version)
        return fileError(path, "the OpenEXR header is truncated");
    const bool multiPart = (static_cast<std::uint32_t>(*version) & kMultiPartFlag) != 0;
    for (;;) {
        bool empty = false;
        if (Status header = checkOneHeader(path, reader, empty); !header)
            return header;
        if (!multiPart || empty)
            return success();
    }
}

} // namespace px

#include "ExrHeaderCheck.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace px {
namespace {

constexpr std::array<unsigned char, 4> kExrMagic = {0x76, 0x2f, 0x31, 0x01};
constexpr std::uint32_t kMultiPartFlag = 0x1000;
constexpr int kMaxNameLength = 255; // with the long-names flag; shorter names are a subset

class HeaderReader {
public:
    explicit HeaderReader(std::string_view bytes) : m_bytes(bytes) {}

    std::int64_t remaining() const { return static_cast<std::int64_t>(m_bytes.size() - m_at); }

    // A NUL-terminated string; nullopt at end of file or when no NUL comes within the limit.
    std::optional<std::string> string() {
        std::string text;
        for (int i = 0; i <= kMaxNameLength; ++i) {
            if (m_at >= m_bytes.size())
                return std::nullopt;
            const char c = m_bytes[m_at++];
            if (c == 0)
                return text;
            text.push_back(c);
        }
        return std::nullopt;
    }

    std::optional<std::int32_t> int32() {
        if (remaining() < 4)
            return std::nullopt;
        std::uint32_t value = 0;
        for (int i = 3; i >= 0; --i)
            value = value << 8U | static_cast<unsigned char>(m_bytes[m_at + i]);
        m_at += 4;
        return static_cast<std::int32_t>(value);
    }

    void skip(std::int32_t bytes) { m_at += static_cast<std::size_t>(bytes); }

private:
    std::string_view m_bytes;
    std::size_t m_at = 4; // past the magic number
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

Status checkExrHeader(const std::string& path, std::string_view bytes) {
    if (bytes.size() < kExrMagic.size() ||
        !std::equal(kExrMagic.begin(), kExrMagic.end(),
                    reinterpret_cast<const unsigned char*>(bytes.data())))
        return success();
    HeaderReader reader(bytes);
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

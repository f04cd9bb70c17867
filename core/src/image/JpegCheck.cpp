#include "JpegCheck.h"

namespace px {
namespace {

constexpr unsigned char kEoi = 0xd9, kSos = 0xda;

bool isRestart(unsigned char marker) {
    return marker >= 0xd0 && marker <= 0xd7;
}

bool isFrame(unsigned char marker) { // SOF0..SOF15 but DHT (c4), JPG (c8), DAC (cc)
    return marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
}

} // namespace

Status checkJpegStructure(const std::string& path, std::string_view bytes) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const std::size_t size = bytes.size();
    auto truncated = [&](const std::string& where) {
        return fileError(path, "the file is truncated (its JPEG data ends at byte " +
                                   std::to_string(size) + " " + where +
                                   ", before the end-of-image marker)");
    };
    bool frame = false, scan = false;
    std::size_t at = 2; // past SOI
    for (;;) {
        // A marker: 0xff, any fill bytes 0xff, then its code.
        if (at >= size)
            return truncated("between segments");
        if (data[at] != 0xff)
            return fileError(path, "the file is damaged (no JPEG marker at byte " +
                                       std::to_string(at) + ")");
        while (at < size && data[at] == 0xff)
            ++at;
        if (at >= size)
            return truncated("between segments");
        const unsigned char marker = data[at++];
        if (marker == kEoi) {
            if (!frame || !scan)
                return fileError(path, "the file is damaged (the JPEG ends before any image data)");
            return success();
        }
        if (isRestart(marker) || marker == 0x01 || marker == 0xd8)
            continue; // no length
        if (at + 2 > size)
            return truncated("in a segment header");
        const std::size_t length = static_cast<std::size_t>(data[at]) << 8 | data[at + 1];
        if (length < 2 || at + length > size)
            return truncated("inside a segment");
        frame = frame || isFrame(marker);
        at += length;
        if (marker != kSos)
            continue;
        scan = true;
        // Entropy-coded data: up to the next marker that is neither a stuffed 0xff00 nor a restart.
        for (;;) {
            while (at < size && data[at] != 0xff)
                ++at;
            if (at + 1 >= size)
                return truncated("inside the image data");
            const unsigned char next = data[at + 1];
            if (next == 0x00 || isRestart(next) || next == 0xff) {
                at += next == 0xff ? 1 : 2;
                continue;
            }
            break;
        }
    }
}

} // namespace px

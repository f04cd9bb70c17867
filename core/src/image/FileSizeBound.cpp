#include "FileSizeBound.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>

namespace px {
namespace {

using i64 = std::int64_t;

i64 divUp(i64 a, i64 b) {
    return (a + b - 1) / b;
}

// Little- and big-endian fields; 0 past the end (then the claim is judged on zeros and the
// decoder reports the short header).
i64 le(std::string_view b, std::size_t at, int n) {
    i64 v = 0;
    for (int i = n - 1; i >= 0; --i)
        v = v << 8 | (at + i < b.size() ? static_cast<unsigned char>(b[at + i]) : 0);
    return v;
}
i64 be(std::string_view b, std::size_t at, int n) {
    i64 v = 0;
    for (int i = 0; i < n; ++i)
        v = v << 8 | (at + i < b.size() ? static_cast<unsigned char>(b[at + i]) : 0);
    return v;
}

// Deflate (PNG, TIFF and EXR zip) tops out at 1032:1, PXR24 deflates floats cut to 3 bytes
// (4/3 more). A baseline JPEG block needs at least 2 bits for 64 samples, i.e. 256 per byte, times
// 3 for 4:2:0 colour. LZW strings grow by one byte per code, so a 12-bit code gives at most 4096
// bytes (2731 per byte). PackBits and EXR's RLE give at most 128 bytes for 2. B44A packs a flat
// block of 16 halves (32 bytes) into 3. Uncompressed data is all in the file. 0: no bound.
i64 maxExpansion(const std::string& format, const std::string& compression) {
    if (format == "jpeg")
        return 768;
    if (compression.empty() || compression == "none")
        return 1;
    if (compression == "zip" || compression == "zips")
        return 1032;
    if (compression == "pxr24")
        return 1376;
    if (compression == "jpeg")
        return 768;
    if (compression == "lzw")
        return 2731;
    if (compression == "packbits" || compression == "rle")
        return 64;
    if (compression == "b44" || compression == "b44a")
        return 11;
    return 0;
}

// Windows BMP: uncompressed rows padded to 4 bytes. RLE may end the bitmap at any point.
StoredClaim bmpClaim(std::string_view b) {
    const i64 offset = le(b, 10, 4);
    if (le(b, 14, 4) == 12) { // OS/2 1.x header: 16-bit sizes, never compressed
        const i64 w = le(b, 18, 2), h = le(b, 20, 2);
        return {w, h, offset + divUp(w * le(b, 24, 2), 32) * 4 * h};
    }
    const i64 width = static_cast<std::int32_t>(le(b, 18, 4));
    i64 height = static_cast<std::int32_t>(le(b, 22, 4));
    height = height < 0 ? -height : height;
    const i64 bits = le(b, 28, 2);
    const i64 compression = le(b, 30, 4);
    if (compression != 0 && compression != 3 && compression != 6)
        return {width, height, 0};
    const i64 stride = divUp(width * bits, 32) * 4;
    return {width, height,
            height > 0 ? offset + stride * (height - 1) + divUp(width * bits, 8) : 0};
}

// Targa: raw texels, or RLE packets of at most 128 texels, each a count byte and a texel.
StoredClaim targaClaim(std::string_view b) {
    const i64 texel = divUp(le(b, 16, 1), 8);
    const i64 colourMap = le(b, 1, 1) != 0 ? le(b, 5, 2) * divUp(le(b, 7, 1), 8) : 0;
    const i64 base = 18 + le(b, 0, 1) + colourMap;
    const i64 w = le(b, 12, 2), h = le(b, 14, 2), texels = w * h;
    switch (le(b, 2, 1)) {
    case 1:
    case 2:
    case 3:
        return {w, h, base + texels * texel};
    case 9:
    case 10:
    case 11:
        return {w, h, base + divUp(texels, 128) * (1 + texel)};
    default:
        return {w, h, 0};
    }
}

// Netpbm: binary P4/P5/P6 and float PF/Pf hold every sample; ASCII P1 a character a sample and
// P2/P3 a digit and a separator.
StoredClaim pnmClaim(std::string_view b) {
    std::size_t at = 2;
    const char kind = b.size() > 1 ? b[1] : 0;
    const int fields = kind == '1' || kind == '4' ? 2 : 3;
    i64 value[3] = {};
    for (int f = 0; f < fields; ++f) {
        for (;;) { // whitespace and comments
            while (at < b.size() && std::isspace(static_cast<unsigned char>(b[at])))
                ++at;
            if (at < b.size() && b[at] == '#')
                while (at < b.size() && b[at] != '\n')
                    ++at;
            else
                break;
        }
        if (f == 2 && (kind == 'F' || kind == 'f')) { // a float scale, not a count
            while (at < b.size() && !std::isspace(static_cast<unsigned char>(b[at])))
                ++at;
            break;
        }
        while (at < b.size() && std::isdigit(static_cast<unsigned char>(b[at])) &&
               value[f] < (i64{1} << 40))
            value[f] = value[f] * 10 + (b[at++] - '0');
    }
    const i64 base = static_cast<i64>(at) + 1, texels = value[0] * value[1];
    const i64 sample = value[2] > 255 ? 2 : 1;
    i64 bytes = 0;
    switch (kind) {
    case '1':
        bytes = base + texels;
        break;
    case '2':
        bytes = base + texels * 2 - 1;
        break;
    case '3':
        bytes = base + texels * 6 - 1;
        break;
    case '4':
        bytes = base + divUp(value[0], 8) * value[1];
        break;
    case '5':
        bytes = base + texels * sample;
        break;
    case '6':
        bytes = base + texels * 3 * sample;
        break;
    case 'f':
        bytes = base + texels * 4;
        break;
    case 'F':
        bytes = base + texels * 12;
        break;
    default:
        break;
    }
    return {value[0], value[1], bytes};
}

// SGI: a 512-byte header, then rows verbatim, or RLE offset and length tables (8 bytes a row) and
// at least one row of packets (rows may share their data), each packet at most 127 texels.
StoredClaim sgiClaim(std::string_view b) {
    const i64 perSample = be(b, 3, 1);
    const i64 dimension = be(b, 4, 2);
    const i64 x = be(b, 6, 2);
    const i64 y = dimension >= 2 ? be(b, 8, 2) : 1;
    const i64 z = dimension >= 3 ? be(b, 10, 2) : 1;
    if (be(b, 2, 1) == 0)
        return {x, y, 512 + x * y * z * perSample};
    return {x, y, 512 + 8 * y * z + (2 * divUp(x, 127) + 1) * perSample};
}

// Radiance: text lines to an empty one, the resolution line, then scanlines of 4-byte texels,
// each flat or (8 to 32767 wide) run-length coded a component at a time, runs of 127 at most.
StoredClaim hdrClaim(std::string_view b) {
    const std::size_t blank = b.find("\n\n");
    if (blank == std::string_view::npos)
        return {};
    const std::size_t end = b.find('\n', blank + 2);
    const std::string line(
        b.substr(blank + 2, end == std::string_view::npos ? 64 : end - blank - 2));
    char axis1[3] = {}, axis2[3] = {};
    long long lines = 0, length = 0;
    if (std::sscanf(line.c_str(), "%2s %lld %2s %lld", axis1, &lines, axis2, &length) != 4 ||
        lines < 0 || length < 0)
        return {};
    const i64 flat = 4 * length;
    const i64 rle = length >= 8 && length <= 0x7fff ? 4 + 8 * divUp(length, 127) : flat;
    const bool rows = axis1[1] == 'Y';
    return {rows ? length : lines, rows ? lines : length,
            static_cast<i64>(blank + 2 + line.size() + 1) + lines * std::min(flat, rle)};
}

// DirectDraw Surface: the top level's blocks (BC1 and BC4: 8 bytes for 4x4 texels, other BCn
// 16) or texels; mipmaps and other faces may follow.
StoredClaim ddsClaim(std::string_view b) {
    const i64 height = le(b, 12, 4), width = le(b, 16, 4);
    const i64 flags = le(b, 80, 4);
    const std::string fourCC(b.substr(std::min<std::size_t>(84, b.size()), 4));
    if ((flags & 0x4) == 0) // uncompressed texels
        return {width, height, 128 + width * height * divUp(le(b, 88, 4), 8)};
    i64 block = 16, base = 128;
    if (fourCC == "DXT1" || fourCC == "ATI1" || fourCC == "BC4U" || fourCC == "BC4S")
        block = 8;
    else if (fourCC == "DX10") {
        const i64 dxgi = le(b, 128, 4);
        base += 20;
        if ((dxgi >= 70 && dxgi <= 72) || (dxgi >= 79 && dxgi <= 81))
            block = 8;
        else if (!(dxgi >= 73 && dxgi <= 84) && !(dxgi >= 94 && dxgi <= 99))
            return {width, height, 0}; // not a block format this bound knows
    }
    return {width, height, base + divUp(width, 4) * divUp(height, 4) * block};
}

} // namespace

std::optional<StoredClaim> claimInHeader(std::string_view bytes, const std::string& format) {
    if (format == "bmp")
        return bmpClaim(bytes);
    if (format == "targa")
        return targaClaim(bytes);
    if (format == "pnm")
        return pnmClaim(bytes);
    if (format == "sgi")
        return sgiClaim(bytes);
    if (format == "hdr")
        return hdrClaim(bytes);
    if (format == "dds")
        return ddsClaim(bytes);
    return std::nullopt;
}

i64 minFileBytes(const ImageHeader& header) {
    const std::string& format = header.format;
    const i64 w = header.width, h = header.height;
    if (format == "png") // a filter byte a row, deflated at best 1032:1
        return 8 + 25 + 12 + divUp(h * (1 + divUp(w * header.bitsPerTexel, 8)), 1032);
    if (format == "jpeg" || format == "tiff" || format == "openexr") {
        const i64 expansion = maxExpansion(format, header.compression);
        return expansion > 0 ? w * h * header.bitsPerTexel / 8 / expansion : 0;
    }
    return 0;
}

} // namespace px

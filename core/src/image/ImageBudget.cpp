#include "ImageBudget.h"

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace px {

namespace {

std::string gigabytes(std::int64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / 1e9);
    return text;
}

} // namespace

// Deflate (PNG, TIFF and EXR zip) tops out at 1032:1, PXR24 deflates floats cut to 3 bytes
// (4/3 more). A baseline JPEG block needs at least 2 bits for 64 samples, i.e. 256 per byte, times
// 3 for 4:2:0 colour. LZW strings grow by one byte per code, so a 12-bit code gives at most 4096
// bytes (2731 per byte). PackBits and EXR's RLE give at most 128 bytes for 2. B44A packs a flat
// block of 16 halves (32 bytes) into 3. Uncompressed data is all in the file.
std::int64_t maxExpansion(const std::string& format, const std::string& compression) {
    if (format == "png")
        return 1032;
    if (format == "jpeg")
        return 768;
    if (format != "tiff" && format != "openexr")
        return 0;
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

std::int64_t availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::int64_t kb = 0;
    std::string unit;
    while (meminfo >> key >> kb >> unit) {
        if (key == "MemAvailable:")
            return kb * 1024;
    }
    const long pages = ::sysconf(_SC_AVPHYS_PAGES);
    const long size = ::sysconf(_SC_PAGESIZE);
    return pages > 0 && size > 0 ? static_cast<std::int64_t>(pages) * size : 0;
}

Status checkImageClaim(const std::string& path, const ImageClaim& claim) {
    const std::string size = std::to_string(claim.width) + "x" + std::to_string(claim.height);
    const std::int64_t raw = claim.width * claim.height * claim.bitsPerTexel / 8;
    const std::int64_t expansion = maxExpansion(claim.format, claim.compression);
    if (expansion > 0 && claim.fileBytes > 0 && raw / expansion > claim.fileBytes)
        return fileError(path, "the header claims " + size + " texels, which a file of " +
                                   std::to_string(claim.fileBytes) +
                                   " bytes cannot hold: the file is damaged or truncated");
    // The float copy readImage makes; loaders make at most one more of a channel.
    const std::int64_t needed = claim.width * claim.height * (claim.channels + 1) * 4;
    const std::int64_t available = availableMemoryBytes();
    if (available > 0 && needed > available)
        return fileError(path, "the image is " + size + " texels and needs " + gigabytes(needed) +
                                   " of memory to read, more than the " + gigabytes(available) +
                                   " available");
    return success();
}

} // namespace px

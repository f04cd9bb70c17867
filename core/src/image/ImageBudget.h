#pragma once
// Checks what an image header claims before any pixel memory is allocated: a 74-byte PNG can
// claim 16384 x 16384 texels (4.3 GB as float) and a damaged one 100000 x 100000.

#include "parallax/Result.h"

#include <cstdint>
#include <string>

namespace px {

struct ImageClaim {
    std::int64_t width = 0, height = 0, channels = 0;
    std::int64_t bitsPerTexel = 8; // all channels as stored in the file (1-bit TIFFs exist)
    std::string format;            // OIIO's format name: "png", "jpeg", "tiff", "openexr", ...
    std::string compression;       // OIIO's "compression" attribute (TIFF, EXR): "zip", ...
    std::int64_t fileBytes = 0;
};

// The most raw bytes one byte of the file can decode to, by format and compression; 0 where no
// bound is known (TIFF ZSTD or LZMA, EXR PIZ or DWA: memory is then the only limit).
std::int64_t maxExpansion(const std::string& format, const std::string& compression);

// Refuses a claim whose pixels cannot come from a file that size (maxExpansion) or whose float
// copy does not fit the memory the machine has available now. Errors name the file, the claim
// and the limit.
Status checkImageClaim(const std::string& path, const ImageClaim& claim);

// Bytes of memory available now (MemAvailable), or 0 if unknown.
std::int64_t availableMemoryBytes();

} // namespace px

#pragma once
// Checks what an image header claims before any pixel memory is allocated: a 74-byte PNG can
// claim 16384 x 16384 texels (4.3 GB as float) and a damaged one 100000 x 100000.

#include "parallax/Result.h"

#include <cstdint>
#include <string>

namespace px {

struct ImageClaim {
    std::int64_t width = 0, height = 0, channels = 0;
    std::int64_t bytesPerSample = 1; // as stored in the file
    std::string format;              // OIIO's format name: "png", "jpeg", "tiff", "openexr", ...
    std::int64_t fileBytes = 0;
};

// Refuses a claim whose pixels cannot come from a file that size (PNG and JPEG: their
// compression cannot expand by more than about 1032:1 and 768:1) or whose float copy does not
// fit the memory the machine has available now. Errors name the file, the claim and the limit.
Status checkImageClaim(const std::string& path, const ImageClaim& claim);

// Bytes of memory available now (MemAvailable), or 0 if unknown.
std::int64_t availableMemoryBytes();

} // namespace px

#pragma once
// Checks what an image header claims before any pixel memory is allocated: a 74-byte PNG can
// claim 16384 x 16384 texels (4.3 GB as float), a 118-byte BMP the same, a damaged file 100000².
// The one rule for every format (docs/image-files.md): the claim must fit the file's size (the
// fewest bytes the format can store it in, FileSizeBound.h) and the memory this process may still
// take (memoryHeadroomBytes).

#include "parallax/Result.h"

#include <cstdint>
#include <string>

namespace px {

struct ImageClaim {
    std::int64_t width = 0, height = 0, channels = 0;
    std::int64_t minFileBytes = 0; // the fewest bytes a file can hold the claim in; 0: no bound
    std::int64_t fileBytes = 0;
};

// Refuses a claim whose pixels cannot come from a file that size or whose float copy does not fit
// the memory the process can still take. Errors name the file, the claim and the limit.
Status checkImageClaim(const std::string& path, const ImageClaim& claim);

// Bytes this process can still allocate: the least of MemAvailable, the room left under
// RLIMIT_AS and RLIMIT_DATA, and the room left under its cgroup's memory limit (v2 memory.max
// minus memory.current, on every level up to the root; v1 limit_in_bytes minus usage_in_bytes).
// 0 if none of them is known.
std::int64_t memoryHeadroomBytes();

} // namespace px

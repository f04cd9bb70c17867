#pragma once
// The fewest bytes a file of each format can store what its header claims in: raw formats need
// every texel, compressed ones at least the raw size over the codec's best ratio. A claim over the
// file's size is a damaged, truncated or lying file (ImageBudget.h), refused before any pixel
// memory is taken.

#include "ImageCodec.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace px {

struct StoredClaim {
    std::int64_t width = 0, height = 0;
    std::int64_t minBytes = 0; // 0: the format allows any size
};

// The claim of a header the core reads itself, before any decoder sees the file (OpenImageIO's
// SGI reader, for one, allocates the RLE tables a header claims as it opens): BMP, Targa, PNM,
// SGI, Radiance HDR and DDS; nullopt for other formats. 0 bytes where the format allows any size
// (BMP RLE's end-of-bitmap).
std::optional<StoredClaim> claimInHeader(std::string_view bytes, const std::string& format);

// The bound for PNG, JPEG, TIFF and OpenEXR from the header their decoder read; 0 for other
// formats and where the compression allows any size (TIFF ZSTD, EXR PIZ or DWA): memory is then
// the only limit.
std::int64_t minFileBytes(const ImageHeader& header);

} // namespace px

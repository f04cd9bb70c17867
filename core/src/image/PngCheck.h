#pragma once
// The guard run before a PNG is decoded: a truncated file or one whose checksums fail is named as
// such, before libpng (PngCodec.h) meets the damage somewhere in the middle of the data.

#include "parallax/Result.h"

#include <string>
#include <string_view>

namespace px {

// True if the bytes start with the PNG signature (the content decides, not the extension).
bool hasPngSignature(std::string_view bytes);

// Walks the chunks of the PNG file `path` whose content is `bytes` (hasPngSignature): each must
// fit in the file and match its CRC, and the file must end with IEND.
Status checkPngStructure(const std::string& path, std::string_view bytes);

} // namespace px

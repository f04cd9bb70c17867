#pragma once
// The guard run before a PNG is decoded: a truncated file or one whose checksums fail is named as
// such, before libpng (PngCodec.h) meets the damage somewhere in the middle of the data.

#include "parallax/Result.h"

#include <string>

namespace px {

// Walks the chunks of a PNG file: each must fit in the file and match its CRC, and the file must
// end with IEND. Files that are not PNG (by their signature) pass untouched.
Status checkPngStructure(const std::string& path);

} // namespace px

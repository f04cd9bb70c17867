#pragma once
// A guard run before libpng sees a file: libpng prints its own "libpng error: ..." line on stderr
// for a truncated or damaged file before OpenImageIO reports it, so the user saw the raw line
// (twice) above the project's message. The chunk structure is checked here first.

#include "parallax/Result.h"

#include <string>

namespace px {

// Walks the chunks of a PNG file: each must fit in the file and match its CRC, and the file must
// end with IEND. Files that are not PNG (by their signature) pass untouched.
Status checkPngStructure(const std::string& path);

} // namespace px

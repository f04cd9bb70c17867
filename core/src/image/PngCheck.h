#pragma once
// Guards run before OpenImageIO's PNG reader sees a file: its libpng prints its own "libpng
// error: ..." line on stderr for a truncated or damaged file before OpenImageIO reports it, so the
// user saw the raw line (twice) above the project's message. The chunk structure is checked here
// first, then the image data is decoded once by libpng with our own error handler.

#include "parallax/Result.h"

#include <string>

namespace px {

// Walks the chunks of a PNG file: each must fit in the file and match its CRC, and the file must
// end with IEND. Files that are not PNG (by their signature) pass untouched.
Status checkPngStructure(const std::string& path);

// Decodes the image data of a PNG (one row at a time, nothing kept) with an error handler that
// keeps libpng's message instead of printing it: damage the checksums miss (a deflate stream that
// does not decode, missing rows) becomes an error naming the file. Run after the header's claim
// was judged; files that are not PNG pass untouched.
Status checkPngData(const std::string& path);

} // namespace px

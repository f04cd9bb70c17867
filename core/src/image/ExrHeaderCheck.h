#pragma once
// A guard run before OpenEXR sees a file: OpenEXR 3.1 allocates whatever size a header attribute
// claims before it notices the file is shorter, so a 600-byte file can cost gigabytes.

#include "parallax/Result.h"

#include <string>
#include <string_view>

namespace px {

// Walks the header attributes of the OpenEXR file `path` whose content is `bytes` (every part of a
// multi-part file) and refuses one whose size is negative or runs past the end of the file. Files
// that are not OpenEXR (by their magic number) pass untouched.
Status checkExrHeader(const std::string& path, std::string_view bytes);

} // namespace px

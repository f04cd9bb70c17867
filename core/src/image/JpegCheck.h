#pragma once
// The guard run before a JPEG is decoded: libjpeg meets a file cut short as a warning ("Premature
// end of JPEG file"), fills the rest grey and reports success, so a third of a photo would be baked
// without a word. Walking the markers to the end-of-image finds it first, baseline or progressive.

#include "parallax/Result.h"

#include <string>
#include <string_view>

namespace px {

// Walks the segments and entropy-coded scans of the JPEG file `path` whose content is `bytes`:
// every segment must fit in the file, a frame and a scan must come, and the end-of-image marker
// must be reached (bytes after it are allowed: phones append data there).
Status checkJpegStructure(const std::string& path, std::string_view bytes);

} // namespace px

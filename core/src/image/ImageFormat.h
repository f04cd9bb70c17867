#pragma once
// Which format a file holds, told by its content (its signature), never by its name: a DDS renamed
// .png is read, and judged, as the DDS it is. Only Targa, which has no signature, is known by its
// extension.

#include <string>
#include <string_view>

namespace px {

// OpenImageIO's name of the format whose signature `bytes` (the file's first bytes, 64 or more
// when the file has them) start with: "png", "jpeg", "tiff", "openexr", "bmp", "hdr", "pnm",
// "sgi", "dds", "psd", "gif", "webp", "ico", "jpeg2000", "heif", "dpx", "cineon", "fits",
// "iff"; "targa" for a `.tga` file that matches none; "" when nothing matches.
std::string imageFormatOf(std::string_view bytes, const std::string& path);

} // namespace px

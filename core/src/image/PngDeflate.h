#pragma once
// A PNG's image data compressed on every core: rows filtered as libpng chooses (the filter of least
// absolute sum), then strips of rows deflated in parallel into one zlib stream, as pigz does (each
// strip raw deflate primed with the 32 KB before it and ended by a sync flush, the last by the
// final block; the Adler-32s combined). Any inflater reads the one stream; the values are those
// given, bit for bit. Writing a 2048² 16-bit map no longer takes a third of a bake on one thread
// (docs/platform.md has the figures).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace px {

struct PngRows {
    int width = 0, height = 0;
    int bytesPerTexel =
        0; // channels times 1 or 2: the distance the Sub/Avg/Paeth filters look back
    // Writes row y's stored bytes (big-endian samples) into `out`, width * bytesPerTexel of them;
    // called from several threads at once, each row once.
    std::function<void(int y, std::uint8_t* out)> row;
};

// Appends the IDAT chunks holding the whole zlib stream of the filtered rows, then IEND, to `file`;
// false if zlib fails (no memory).
bool appendPngImageData(const PngRows& rows, int level, std::vector<unsigned char>& file);

} // namespace px

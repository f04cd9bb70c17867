#include "PngDeflate.h"

#include <algorithm>
#include <cstdlib>
#include <tbb/parallel_for.h>
#include <zlib.h>

namespace px {
namespace {

constexpr std::size_t kWindow = 32768;
constexpr std::size_t kStripBytes =
    512 * 1024;                              // filtered bytes a strip: enough to amortise a flush
constexpr std::size_t kChunkBytes = 1 << 20; // the largest IDAT written

int paeth(int a, int b, int c) {
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// The filtered byte of each PNG filter type (0 None, 1 Sub, 2 Up, 3 Average, 4 Paeth); `a` the byte
// bpp to the left, `b` the one above, `c` above that left.
template <int Type> std::uint8_t filtered(int x, int a, int b, int c) {
    if constexpr (Type == 0)
        return static_cast<std::uint8_t>(x);
    else if constexpr (Type == 1)
        return static_cast<std::uint8_t>(x - a);
    else if constexpr (Type == 2)
        return static_cast<std::uint8_t>(x - b);
    else if constexpr (Type == 3)
        return static_cast<std::uint8_t>(x - (a + b) / 2);
    else
        return static_cast<std::uint8_t>(x - paeth(a, b, c));
}

// Filters `raw` (above: the previous row, zeros for the first) by `Type` into `out`; returns the
// sum of the results read as signed bytes, in magnitude.
template <int Type>
std::uint64_t filterAs(const std::uint8_t* raw, const std::uint8_t* above, std::size_t size,
                       std::size_t bpp, std::uint8_t* out) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < size; ++i) {
        const bool left = i >= bpp;
        const std::uint8_t v =
            filtered<Type>(raw[i], left ? raw[i - bpp] : 0, above[i], left ? above[i - bpp] : 0);
        out[i] = v;
        sum += v < 128 ? v : 256 - v;
    }
    return sum;
}

// The filter whose bytes, read as signed, sum least in magnitude (libpng's default heuristic for
// 8- and 16-bit images) into `out`: the filter byte, then the row.
void filterRow(const std::uint8_t* raw, const std::uint8_t* above, std::size_t size, int bpp,
               std::vector<std::uint8_t>& trial, std::uint8_t* out) {
    using Filter = std::uint64_t (*)(const std::uint8_t*, const std::uint8_t*, std::size_t,
                                     std::size_t, std::uint8_t*);
    static constexpr Filter kFilters[5] = {filterAs<0>, filterAs<1>, filterAs<2>, filterAs<3>,
                                           filterAs<4>};
    std::uint64_t best = kFilters[0](raw, above, size, static_cast<std::size_t>(bpp), out + 1);
    out[0] = 0;
    for (int type = 1; type < 5; ++type) {
        const std::uint64_t sum =
            kFilters[type](raw, above, size, static_cast<std::size_t>(bpp), trial.data());
        if (sum < best) {
            best = sum;
            out[0] = static_cast<std::uint8_t>(type);
            std::copy(trial.begin(), trial.begin() + static_cast<std::ptrdiff_t>(size), out + 1);
        }
    }
}

void putBig32(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<unsigned char>(v >> shift));
}

void appendChunk(std::vector<unsigned char>& file, const char* type, const unsigned char* data,
                 std::size_t size) {
    putBig32(file, static_cast<std::uint32_t>(size));
    const std::size_t start = file.size();
    file.insert(file.end(), type, type + 4);
    file.insert(file.end(), data, data + size);
    putBig32(file, static_cast<std::uint32_t>(
                       ::crc32(0, file.data() + start, static_cast<uInt>(size + 4))));
}

} // namespace

bool appendPngImageData(const PngRows& rows, int level, std::vector<unsigned char>& file) {
    const std::size_t rowBytes = static_cast<std::size_t>(rows.width) * rows.bytesPerTexel;
    const std::size_t lineBytes = rowBytes + 1; // with its filter byte
    const int rowsPerStrip =
        static_cast<int>(std::clamp<std::size_t>(kStripBytes / lineBytes, 1, rows.height));
    const int strips = (rows.height + rowsPerStrip - 1) / rowsPerStrip;
    std::vector<std::uint8_t> filtered(lineBytes * rows.height);
    std::vector<std::vector<unsigned char>> deflated(strips);
    std::vector<uLong> adlers(strips);
    std::vector<char> failed(strips, 0);

    // Filtered first, every strip: each strip's deflate is primed with the bytes before it.
    tbb::parallel_for(0, strips, [&](int s) {
        const int y0 = s * rowsPerStrip, y1 = std::min(rows.height, y0 + rowsPerStrip);
        std::vector<std::uint8_t> above(rowBytes, 0), raw(rowBytes), trial(rowBytes);
        if (y0 > 0)
            rows.row(y0 - 1, above.data()); // made again here, not shared with the strip above
        for (int y = y0; y < y1; ++y) {
            rows.row(y, raw.data());
            filterRow(raw.data(), above.data(), rowBytes, rows.bytesPerTexel, trial,
                      filtered.data() + lineBytes * y);
            std::swap(raw, above);
        }
    });
    // Deflated, raw, each strip primed with the window before it: as good as one stream, nearly.
    tbb::parallel_for(0, strips, [&](int s) {
        const int y0 = s * rowsPerStrip, y1 = std::min(rows.height, y0 + rowsPerStrip);
        const std::uint8_t* begin = filtered.data() + lineBytes * y0;
        const std::size_t size = lineBytes * (y1 - y0);
        z_stream z{};
        if (deflateInit2(&z, level, Z_DEFLATED, -15, 8, Z_FILTERED) != Z_OK) {
            failed[s] = 1;
            return;
        }
        if (s > 0) {
            const std::size_t before = std::min(kWindow, lineBytes * y0);
            deflateSetDictionary(&z, begin - before, static_cast<uInt>(before));
        }
        std::vector<unsigned char>& out = deflated[s];
        out.resize(deflateBound(&z, size) + 16);
        z.next_in = const_cast<std::uint8_t*>(begin);
        z.avail_in = static_cast<uInt>(size);
        z.next_out = out.data();
        z.avail_out = static_cast<uInt>(out.size());
        const int done = deflate(&z, s + 1 == strips ? Z_FINISH : Z_SYNC_FLUSH);
        failed[s] = done != (s + 1 == strips ? Z_STREAM_END : Z_OK) || z.avail_in != 0;
        out.resize(out.size() - z.avail_out);
        deflateEnd(&z);
        adlers[s] = adler32(adler32(0, nullptr, 0), begin, static_cast<uInt>(size));
    });

    if (std::find(failed.begin(), failed.end(), 1) != failed.end())
        return false;
    // One zlib stream: its header, the strips in order, the Adler-32 of all the filtered bytes.
    const int levelFlag = level == 1                ? 0
                          : level < 6 && level >= 0 ? 1
                          : level == 6 || level < 0 ? 2
                                                    : 3;
    std::vector<unsigned char> stream{0x78, 0};
    stream[1] = static_cast<unsigned char>(levelFlag << 6);
    stream[1] = static_cast<unsigned char>(stream[1] + 31 - (0x78 * 256 + stream[1]) % 31);
    uLong adler = adler32(0, nullptr, 0);
    for (int s = 0; s < strips; ++s) {
        stream.insert(stream.end(), deflated[s].begin(), deflated[s].end());
        const int y0 = s * rowsPerStrip, y1 = std::min(rows.height, y0 + rowsPerStrip);
        adler = adler32_combine(adler, adlers[s], static_cast<z_off_t>(lineBytes * (y1 - y0)));
    }
    putBig32(stream, static_cast<std::uint32_t>(adler));
    for (std::size_t at = 0; at < stream.size(); at += kChunkBytes)
        appendChunk(file, "IDAT", stream.data() + at, std::min(kChunkBytes, stream.size() - at));
    appendChunk(file, "IEND", nullptr, 0);
    return true;
}

} // namespace px

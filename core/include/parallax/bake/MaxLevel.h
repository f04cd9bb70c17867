#pragma once
// One level of a maximum pyramid, and the levels above it: each node holds the maximum of its up
// to four children, sizes rounded up so an odd last row or column is kept, never dropped. The
// `pyramid` technique's MaxMipPyramid and the cone bakers' pyramid of cells are both built so.

#include <cstddef>
#include <vector>

namespace px {

struct MaxLevel {
    int width = 0;
    int height = 0;
    std::vector<float> values; // row-major, width * height

    float at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
};

// `base` followed by the levels above it, up to a 1 x 1 top; just `base` if it is 1 x 1 or empty.
std::vector<MaxLevel> maxPyramid(MaxLevel base);

} // namespace px

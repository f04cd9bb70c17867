#pragma once
// The maximum mipmap the `pyramid` technique walks (docs/cone-maps.md §4). Level 0 holds one value
// per cell, the max of its four corner texels; the levels above as maxPyramid builds them
// (MaxLevel.h: sizes rounded up so odd sizes lose nothing).
//   repeat: W x H cells, cell (i, j) spans texels i..i+1 mod W and j..j+1 mod H;
//   clamp: (W+1) x (H+1) cells, index i+1 for cell i = -1..W-1 (the outer ones are the half-texel
//          border strips, whose corners clamp to the edge texels).

#include "parallax/bake/MaxLevel.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"

#include <cstddef>
#include <vector>

namespace px {

class MaxMipPyramid {
public:
    MaxMipPyramid() = default;
    static MaxMipPyramid build(const HeightField& field, WrapMode wrap);

    WrapMode wrap() const { return m_wrap; }
    int levels() const { return static_cast<int>(m_levels.size()); }
    int top() const { return levels() - 1; }
    int width(int level) const { return m_levels[level].width; }
    int height(int level) const { return m_levels[level].height; }
    float at(int level, int x, int y) const { return m_levels[level].at(x, y); }

    // One level as a one-channel image, for inspection and export.
    Image levelImage(int level) const;
    // Every level packed into one image, level L starting at row atlasRow(L): what the GPU reads
    // with texelFetch (GL mip chains round sizes down, which would drop odd rows and columns).
    Image atlas() const;
    int atlasRow(int level) const;

private:
    WrapMode m_wrap = WrapMode::Repeat;
    std::vector<MaxLevel> m_levels;
};

} // namespace px

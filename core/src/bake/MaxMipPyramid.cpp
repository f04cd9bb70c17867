#include "parallax/bake/MaxMipPyramid.h"

#include <algorithm>

namespace px {

MaxMipPyramid MaxMipPyramid::build(const HeightField& field, WrapMode wrap) {
    MaxMipPyramid pyramid;
    pyramid.m_wrap = wrap;
    if (field.empty())
        return pyramid;

    // Clamp adds the two half-texel border strips: stored index s is cell s - 1.
    const int offset = wrap == WrapMode::Clamp ? 1 : 0;
    MaxLevel base;
    base.width = field.width + offset;
    base.height = field.height + offset;
    base.values.resize(static_cast<std::size_t>(base.width) * base.height);
    for (int y = 0; y < base.height; ++y) {
        for (int x = 0; x < base.width; ++x) {
            const int x0 = wrapIndex(x - offset, field.width, wrap);
            const int x1 = wrapIndex(x - offset + 1, field.width, wrap);
            const int y0 = wrapIndex(y - offset, field.height, wrap);
            const int y1 = wrapIndex(y - offset + 1, field.height, wrap);
            base.values[static_cast<std::size_t>(y) * base.width + x] =
                std::max({field.at(x0, y0), field.at(x1, y0), field.at(x0, y1), field.at(x1, y1)});
        }
    }
    pyramid.m_levels = maxPyramid(std::move(base));
    return pyramid;
}

Image MaxMipPyramid::levelImage(int level) const {
    const MaxLevel& l = m_levels[level];
    Image image(l.width, l.height, 1);
    image.pixels = l.values;
    return image;
}

int MaxMipPyramid::atlasRow(int level) const {
    int row = 0;
    for (int l = 0; l < level; ++l)
        row += m_levels[l].height;
    return row;
}

Image MaxMipPyramid::atlas() const {
    if (m_levels.empty())
        return {};
    Image image(m_levels[0].width, atlasRow(levels()), 1);
    const ImageWriter put = image.writer();
    for (int l = 0; l < levels(); ++l) {
        const int row = atlasRow(l);
        for (int y = 0; y < height(l); ++y) {
            for (int x = 0; x < width(l); ++x)
                put.at(x, row + y) = at(l, x, y);
        }
    }
    return image;
}

} // namespace px

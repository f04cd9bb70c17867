#include "parallax/bake/BakeEncoding.h"

#include "parallax/bake/ConeMapFinish.h"

#include <algorithm>
#include <cmath>

namespace px {

int quantisationSteps(PixelFormat format) {
    switch (format) {
    case PixelFormat::UInt8:
        return 255;
    case PixelFormat::UInt16:
        return 65535;
    case PixelFormat::Half:
    case PixelFormat::Float:
        return 0;
    }
    return 0;
}

float roundUpToStep(float v, int steps) {
    if (steps == 0)
        return v;
    const float scale = static_cast<float>(steps);
    float k = std::ceil(std::clamp(v, 0.0f, 1.0f) * scale);
    // The product may round either way: settle on the first step that is not below v.
    while (k > 0.0f && (k - 1.0f) / scale >= v)
        k -= 1.0f;
    while (k < scale && k / scale < v)
        k += 1.0f;
    return k / scale;
}

HeightField roundHeightsUp(const HeightField& field, PixelFormat format) {
    HeightField rounded = field;
    const int steps = quantisationSteps(format);
    for (float& h : rounded.texels)
        h = roundUpToStep(h, steps);
    return rounded;
}

Image encodeConeMap(const HeightField& heights, ConeMap g, PixelFormat format) {
    Image image(g.width, g.height, 3);
    const ImageWriter put = image.writer();
    const int steps = quantisationSteps(format);
    if (steps > 0)
        quantiseDown(g, steps);
    for (int y = 0; y < g.height; ++y) {
        for (int x = 0; x < g.width; ++x) {
            put.at(x, y, 0) = roundUpToStep(heights.at(x, y), steps);
            put.at(x, y, 1) = g.g(x, y);
        }
    }
    return image;
}

Image encodePyramid(const MaxMipPyramid& pyramid, PyramidLayout layout, int level,
                    PixelFormat format) {
    Image image;
    if (level >= 0) {
        image = pyramid.levelImage(level);
    } else if (layout == PyramidLayout::Atlas) {
        image = pyramid.atlas();
    } else {
        int right = 0, column = 0;
        for (int l = 1; l < pyramid.levels(); ++l) {
            right = std::max(right, pyramid.width(l));
            column += pyramid.height(l);
        }
        image = Image(pyramid.width(0) + right, std::max(pyramid.height(0), column), 1);
        const ImageWriter put = image.writer();
        int row = 0;
        for (int l = 0; l < pyramid.levels(); ++l) {
            const int x0 = l == 0 ? 0 : pyramid.width(0), y0 = l == 0 ? 0 : row;
            for (int y = 0; y < pyramid.height(l); ++y) {
                for (int x = 0; x < pyramid.width(l); ++x)
                    put.at(x0 + x, y0 + y) = pyramid.at(l, x, y);
            }
            if (l > 0)
                row += pyramid.height(l);
        }
    }
    const int steps = quantisationSteps(format);
    for (float& v : image.pixels)
        v = roundUpToStep(v, steps);
    return image;
}

} // namespace px

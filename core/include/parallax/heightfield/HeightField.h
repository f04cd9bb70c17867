#pragma once
// A height map as the core sees it: W×H floats in [0,1], white = high (docs/conventions.md §2).

#include "parallax/image/Image.h"

#include <cstddef>
#include <vector>

namespace px {

struct HeightField {
    int width = 0;
    int height = 0;
    SharedTexels<float> texels; // row-major, row 0 = top of the image (v = 0)

    HeightField() = default;
    HeightField(int w, int h, float value = 0.0f)
        : width(w), height(h), texels(static_cast<std::size_t>(w) * h, value) {}

    float& at(int x, int y) { return texels[static_cast<std::size_t>(y) * width + x]; }
    float at(int x, int y) const { return texels[static_cast<std::size_t>(y) * width + x]; }
    PlaneWriter writer() { return {texels.data(), width}; } // Image.h
    bool empty() const { return width <= 0 || height <= 0; }

    float maxHeight() const;
    float minHeight() const;
    Image toImage() const; // one channel
};

} // namespace px

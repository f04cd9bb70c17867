#pragma once
// A W×H image of float channels, row 0 at the top of the file (docs/conventions.md §1: no flips).

#include "parallax/image/SharedTexels.h"

#include <cstddef>

namespace px {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    SharedTexels<float> pixels; // row-major, interleaved channels
    bool alphaOnly = false;     // one channel, which the file names alpha (an EXR's "A")

    Image() = default;
    Image(int w, int h, int c)
        : width(w), height(h), channels(c), pixels(static_cast<std::size_t>(w) * h * c, 0.0f) {}

    std::size_t index(int x, int y, int c = 0) const {
        return (static_cast<std::size_t>(y) * width + x) * channels + c;
    }
    float& at(int x, int y, int c = 0) { return pixels[index(x, y, c)]; }
    float at(int x, int y, int c = 0) const { return pixels[index(x, y, c)]; }
    bool empty() const { return width <= 0 || height <= 0 || channels <= 0; }
};

} // namespace px

#pragma once
// A W×H image of float channels, row 0 at the top of the file (docs/conventions.md §1: no flips).

#include "parallax/image/SharedTexels.h"

#include <cstddef>

namespace px {

// Writing many texels of an image (Image::writer()): its texels made its own once, then plain
// pointer writes the compiler can vectorise; at() tests ownership on every write
// (SharedTexels.h), which keeps a fill loop scalar. Valid until the image is copied or assigned.
struct ImageWriter {
    float* texels;
    int width;
    int channels;
    float& at(int x, int y, int c = 0) const {
        return texels[(static_cast<std::size_t>(y) * width + x) * channels + c];
    }
};

// The same for a one-channel plane (HeightField::writer(), ConeMap::writer()). Take it before a
// parallel loop: writers on several threads through at() would each try to make the texels their
// own at once.
struct PlaneWriter {
    float* texels;
    int width;
    float& at(int x, int y) const { return texels[static_cast<std::size_t>(y) * width + x]; }
};

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
    ImageWriter writer() { return {pixels.data(), width, channels}; }
    bool empty() const { return width <= 0 || height <= 0 || channels <= 0; }
};

} // namespace px

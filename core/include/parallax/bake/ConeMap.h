#pragma once
// A cone map in memory (docs/conventions.md §4): per texel the square root of the cone ratio, as
// the G channel stores it; the ratio itself is c = g^2, in uv units per unit of normalised height.
// Heights (the R channel on disk) come from the height field the map was baked from.

#include "parallax/image/Image.h"
#include "parallax/image/SharedTexels.h"

#include <cstddef>

namespace px {

enum class ConeKind { Conservative, Relaxed };

struct ConeMap {
    ConeKind kind = ConeKind::Conservative;
    int width = 0;
    int height = 0;
    SharedTexels<float> sqrtRatio; // row-major, in [0, 1]

    ConeMap() = default;
    ConeMap(ConeKind k, int w, int h)
        : kind(k), width(w), height(h), sqrtRatio(static_cast<std::size_t>(w) * h, 1.0f) {}

    float& g(int x, int y) { return sqrtRatio[static_cast<std::size_t>(y) * width + x]; }
    float g(int x, int y) const { return sqrtRatio[static_cast<std::size_t>(y) * width + x]; }
    PlaneWriter writer() { return {sqrtRatio.data(), width}; } // Image.h
    float ratio(int x, int y) const { return g(x, y) * g(x, y); }
};

} // namespace px

#include "Orientation.h"

#include <algorithm>

namespace px {

Image upright(const Image& stored, int orientation) {
    if (orientation <= 1 || orientation > 8)
        return stored;
    const int w = stored.width, h = stored.height, c = stored.channels;
    const bool swaps = orientation >= 5;
    Image out(swaps ? h : w, swaps ? w : h, c);
    out.alphaOnly = stored.alphaOnly;
    const float* in = stored.pixels.data();
    ImageWriter write = out.writer();
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            int sx = x, sy = y; // the stored texel shown at (x, y)
            switch (orientation) {
            case 2:
                sx = w - 1 - x;
                break;
            case 3:
                sx = w - 1 - x;
                sy = h - 1 - y;
                break;
            case 4:
                sy = h - 1 - y;
                break;
            case 5:
                sx = y;
                sy = x;
                break;
            case 6:
                sx = y;
                sy = h - 1 - x;
                break;
            case 7:
                sx = w - 1 - y;
                sy = h - 1 - x;
                break;
            case 8:
                sx = w - 1 - y;
                sy = x;
                break;
            default:
                break;
            }
            const float* from = in + (static_cast<std::size_t>(sy) * w + sx) * c;
            std::copy(from, from + c, &write.at(x, y));
        }
    }
    return out;
}

std::string orientationChange(int orientation) {
    switch (orientation) {
    case 2:
        return "mirrored left to right";
    case 3:
        return "rotated 180°";
    case 4:
        return "flipped top to bottom";
    case 5:
        return "transposed (mirrored about its main diagonal)";
    case 6:
        return "rotated 90° clockwise";
    case 7:
        return "transposed about its other diagonal";
    case 8:
        return "rotated 90° anticlockwise";
    default:
        return {};
    }
}

} // namespace px

// Loaded normal maps: green conversion (pass-through) and telling their convention.

#include "parallax/bake/NormalMapBaker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace px {

Result<Image> convertNormalMap(const Image& normals, NormalGreen from, NormalGreen to,
                               const std::string& source) {
    if (normals.empty())
        return fileError(source, "the normal map is empty");
    if (normals.channels < 2)
        return fileError(source,
                         "a normal map needs at least red and green, this image has one channel");
    const bool flip = from != to;
    Image out(normals.width, normals.height, 3);
    const ImageWriter put = out.writer();
    for (int y = 0; y < normals.height; ++y) {
        for (int x = 0; x < normals.width; ++x) {
            const float r = normals.at(x, y, 0), g = normals.at(x, y, 1);
            float b;
            if (normals.channels >= 3) {
                b = normals.at(x, y, 2);
            } else {
                // Two-channel maps (BC5 style) store X and Y only: Z from unit length.
                const float nx = 2.0f * r - 1.0f, ny = 2.0f * g - 1.0f;
                b = std::sqrt(std::max(0.0f, 1.0f - nx * nx - ny * ny)) * 0.5f + 0.5f;
            }
            put.at(x, y, 0) = r;
            put.at(x, y, 1) = flip ? 1.0f - g : g;
            put.at(x, y, 2) = b;
        }
    }
    return out;
}

namespace {

struct Pearson {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, n = 0;
    void add(double a, double b) {
        sa += a;
        sb += b;
        saa += a * a;
        sbb += b * b;
        sab += a * b;
        n += 1;
    }
    double r() const {
        if (n < 2)
            return 0.0;
        const double cov = sab / n - (sa / n) * (sb / n);
        const double va = saa / n - (sa / n) * (sa / n), vb = sbb / n - (sb / n) * (sb / n);
        return va > 1e-12 && vb > 1e-12 ? cov / std::sqrt(va * vb) : 0.0;
    }
};

} // namespace

SlopeCorrelation correlateWithSlopes(const Image& normals, const HeightField& field,
                                     WrapMode wrap) {
    if (normals.empty() || normals.channels < 2 || field.empty())
        return {};
    // Central differences of the height at each normal texel's centre (nearest height texel).
    Pearson across, down;
    for (int y = 0; y < normals.height; ++y) {
        const int hy = static_cast<int>((y + 0.5) * field.height / normals.height);
        const int y0 = wrapIndex(hy - 1, field.height, wrap),
                  y1 = wrapIndex(hy + 1, field.height, wrap);
        for (int x = 0; x < normals.width; ++x) {
            const int hx = static_cast<int>((x + 0.5) * field.width / normals.width);
            const int x0 = wrapIndex(hx - 1, field.width, wrap),
                      x1 = wrapIndex(hx + 1, field.width, wrap);
            across.add(normals.at(x, y, 0),
                       -(static_cast<double>(field.at(x1, hy)) - field.at(x0, hy)));
            down.add(normals.at(x, y, 1), static_cast<double>(field.at(hx, y1)) - field.at(hx, y0));
        }
    }
    return {across.r(), down.r()};
}

Result<NormalGreen> detectNormalGreen(const Image& normals, const HeightField& field, WrapMode wrap,
                                      const std::string& source) {
    if (normals.empty() || normals.channels < 2)
        return fileError(source, "a normal map needs at least red and green channels");
    if (field.empty())
        return Error{"the height map is empty"};
    // OpenGL: n_y has the sign of +dh/dv.
    const double r = correlateWithSlopes(normals, field, wrap).down;
    if (r == 0.0)
        return fileError(source, "cannot tell the green convention: the normal map or the height "
                                 "map is flat");
    if (std::abs(r) < 0.05) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "cannot tell the green convention: green does not correlate with the height "
                      "map's slope (r = %.3f); is it the normal map of this height map?",
                      r);
        return fileError(source, text);
    }
    return r > 0 ? NormalGreen::OpenGL : NormalGreen::DirectX;
}

} // namespace px

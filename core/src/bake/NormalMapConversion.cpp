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
            out.at(x, y, 0) = r;
            out.at(x, y, 1) = flip ? 1.0f - g : g;
            out.at(x, y, 2) = b;
        }
    }
    return out;
}

Result<NormalGreen> detectNormalGreen(const Image& normals, const HeightField& field, WrapMode wrap,
                                      const std::string& source) {
    if (normals.empty() || normals.channels < 2)
        return fileError(source, "a normal map needs at least red and green channels");
    if (field.empty())
        return Error{"the height map is empty"};
    // Pearson correlation of green with dh/dv at the normal map's texel centres (OpenGL: n_y has
    // the sign of +dh/dv).
    double sg = 0, sd = 0, sgg = 0, sdd = 0, sgd = 0;
    const double n = static_cast<double>(normals.width) * normals.height;
    for (int y = 0; y < normals.height; ++y) {
        const int hy = static_cast<int>((y + 0.5) * field.height / normals.height);
        const int y0 = wrapIndex(hy - 1, field.height, wrap),
                  y1 = wrapIndex(hy + 1, field.height, wrap);
        for (int x = 0; x < normals.width; ++x) {
            const int hx = static_cast<int>((x + 0.5) * field.width / normals.width);
            const double d = static_cast<double>(field.at(hx, y1)) - field.at(hx, y0);
            const double g = normals.at(x, y, 1);
            sg += g;
            sd += d;
            sgg += g * g;
            sdd += d * d;
            sgd += g * d;
        }
    }
    const double cov = sgd / n - (sg / n) * (sd / n);
    const double vg = sgg / n - (sg / n) * (sg / n), vd = sdd / n - (sd / n) * (sd / n);
    if (vg <= 1e-12 || vd <= 1e-12)
        return fileError(source, "cannot tell the green convention: the normal map or the height "
                                 "map is flat");
    const double r = cov / std::sqrt(vg * vd);
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

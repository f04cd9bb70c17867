#include "parallax/material/MapContent.h"

#include <algorithm>
#include <cmath>

namespace px {

namespace {

// Every step-th texel in both directions, so that at most about 512 x 512 are looked at.
int sampleStep(const Image& image) {
    return std::max(1, std::max(image.width, image.height) / 512);
}

} // namespace

ImageTraits imageTraits(const Image& image) {
    ImageTraits t;
    if (image.empty())
        return t;
    const int step = sampleStep(image);
    double sumColour = 0.0, sumZ = 0.0, sumLength = 0.0, sumX = 0.0, sumY = 0.0;
    long n = 0, colourful = 0, outward = 0, unit = 0;
    float alphaLo = 1e30f, alphaHi = -1e30f;
    for (int y = 0; y < image.height; y += step) {
        for (int x = 0; x < image.width; x += step) {
            ++n;
            if (image.channels == 2 || image.channels >= 4) {
                const float a = image.at(x, y, image.channels - 1);
                alphaLo = std::min(alphaLo, a);
                alphaHi = std::max(alphaHi, a);
            }
            if (image.channels < 3)
                continue;
            const float r = image.at(x, y, 0), g = image.at(x, y, 1), b = image.at(x, y, 2);
            const float spread = std::max({r, g, b}) - std::min({r, g, b});
            sumColour += spread;
            colourful += spread > 0.06f;
            const double nx = 2.0 * r - 1.0, ny = 2.0 * g - 1.0, nz = 2.0 * b - 1.0;
            const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
            sumX += nx;
            sumY += ny;
            sumZ += nz;
            sumLength += length;
            outward += nz >= -0.02;
            unit += std::abs(length - 1.0) < 0.2;
        }
    }
    t.alphaVaries = alphaHi - alphaLo > 2.0f / 255.0f;
    if (image.channels < 3) {
        t.grey = true;
        return t;
    }
    const double count = static_cast<double>(n);
    // JPEG leaves a little colour in grey images: on average under 2%, rarely over 6%.
    t.grey = sumColour / count < 0.02 && colourful < n / 100;
    t.meanZ = sumZ / count;
    t.meanLength = sumLength / count;
    const double meanX = sumX / count, meanY = sumY / count;
    t.normalLike = !t.grey && t.meanZ > 0.5 && outward >= n * 98 / 100 && unit >= n * 9 / 10 &&
                   std::abs(meanX) < 0.25 && std::abs(meanY) < 0.25;
    return t;
}

HeightField channelField(const Image& image, int channel) {
    HeightField field(image.width, image.height);
    const PlaneWriter put = field.writer();
    const int c = std::min(channel, image.channels - 1);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x)
            put.at(x, y) = image.at(x, y, c);
    }
    return field;
}

GreenFromCurl greenFromCurl(const Image& normals) {
    GreenFromCurl out;
    if (normals.channels < 3 || normals.width < 3 || normals.height < 3)
        return out;
    // Slopes under OpenGL green: p = dh/du = -nx/nz, q = dh/dv = ny/nz (docs/conventions.md §3).
    auto slopes = [&](int x, int y) {
        const double nx = 2.0 * normals.at(x, y, 0) - 1.0, ny = 2.0 * normals.at(x, y, 1) - 1.0;
        const double nz = std::max(2.0 * normals.at(x, y, 2) - 1.0, 0.05);
        return std::pair{-nx / nz, ny / nz};
    };
    // The mixed derivatives dp/dv and dq/du of each 2 x 2 cell agree for a gradient; DirectX
    // green flips q. Cells spread over the map, at most about 512 x 512 of them.
    const int step = sampleStep(normals);
    double same = 0.0, flipped = 0.0;
    for (int y = 0; y + 1 < normals.height; y += step) {
        for (int x = 0; x + 1 < normals.width; x += step) {
            const auto [p00, q00] = slopes(x, y);
            const auto [p10, q10] = slopes(x + 1, y);
            const auto [p01, q01] = slopes(x, y + 1);
            const auto [p11, q11] = slopes(x + 1, y + 1);
            const double a = (p01 + p11) - (p00 + p10);
            const double b = (q10 + q11) - (q00 + q01);
            same += (a - b) * (a - b);
            flipped += (a + b) * (a + b);
        }
    }
    if (same <= 0.0 && flipped <= 0.0)
        return out;
    out.green = same <= flipped ? NormalGreen::OpenGL : NormalGreen::DirectX;
    const double lo = std::min(same, flipped), hi = std::max(same, flipped);
    out.clarity = lo > 0.0 ? hi / lo : 1e9;
    return out;
}

} // namespace px

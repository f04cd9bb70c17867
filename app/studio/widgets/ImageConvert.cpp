#include "widgets/ImageConvert.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace px::studio {

namespace {

// Box-filters a W x H source of `channels` values, read by `at`, into an 8-bit RGB image.
QImage downsample(int w, int h, int channels, int maxSide,
                  const std::function<float(int, int, int)>& at) {
    if (w <= 0 || h <= 0)
        return {};
    const int step = std::max(1, static_cast<int>(std::ceil(std::max(w, h) / double(maxSide))));
    const int ow = std::max(1, w / step), oh = std::max(1, h / step);
    QImage out(ow, oh, QImage::Format_RGB888);
    for (int y = 0; y < oh; ++y) {
        uchar* line = out.scanLine(y);
        for (int x = 0; x < ow; ++x) {
            float sum[3] = {0, 0, 0};
            int n = 0;
            for (int sy = y * step; sy < std::min(h, (y + 1) * step); ++sy) {
                for (int sx = x * step; sx < std::min(w, (x + 1) * step); ++sx) {
                    for (int c = 0; c < 3; ++c)
                        sum[c] += at(sx, sy, std::min(c, channels - 1));
                    ++n;
                }
            }
            for (int c = 0; c < 3; ++c)
                line[x * 3 + c] = static_cast<uchar>(
                    std::lround(std::clamp(sum[c] / std::max(1, n), 0.0f, 1.0f) * 255.0f));
        }
    }
    return out;
}

} // namespace

QImage toQImage(const Image& image, int maxSide) {
    return downsample(image.width, image.height, std::min(image.channels, 3), maxSide,
                      [&](int x, int y, int c) { return image.at(x, y, c); });
}

QImage toQImage(const HeightField& field, int maxSide) {
    return downsample(field.width, field.height, 1, maxSide,
                      [&](int x, int y, int) { return field.at(x, y); });
}

QImage toQImage(const ConeMap& cone, int maxSide) {
    return downsample(cone.width, cone.height, 1, maxSide,
                      [&](int x, int y, int) { return cone.g(x, y); });
}

} // namespace px::studio

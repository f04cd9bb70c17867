#include "widgets/ImageConvert.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace px::studio {

namespace {

// Box-filters a W x H source of `channels` (1 or 3) values, read by `at(x, y, c)`, into an 8-bit
// RGB image. A template, not a std::function: the editor redraws a map's thumbnail on the GUI
// thread after each load and bake, and a call per texel and channel cost 0.27 s there at 4096²
// (perf, llvmpipe run of the memory benchmark).
template <class At> QImage downsample(int w, int h, int channels, int maxSide, const At& at) {
    if (w <= 0 || h <= 0)
        return {};
    const int step = std::max(1, static_cast<int>(std::ceil(std::max(w, h) / double(maxSide))));
    const int ow = std::max(1, w / step), oh = std::max(1, h / step);
    QImage out(ow, oh, QImage::Format_RGB888);
    std::vector<float> sums(static_cast<std::size_t>(ow) * 3);
    for (int y = 0; y < oh; ++y) {
        std::fill(sums.begin(), sums.end(), 0.0f);
        const int y1 = std::min(h, (y + 1) * step);
        for (int sy = y * step; sy < y1; ++sy) {
            for (int x = 0; x < ow; ++x) {
                float* sum = &sums[static_cast<std::size_t>(x) * 3];
                for (int c = 0; c < channels; ++c) {
                    float s = 0.0f;
                    for (int sx = x * step; sx < (x + 1) * step; ++sx)
                        s += at(sx, sy, c);
                    sum[c] += s;
                }
            }
        }
        const float n = static_cast<float>((y1 - y * step) * step);
        uchar* line = out.scanLine(y);
        for (int x = 0; x < ow; ++x) {
            for (int c = 0; c < 3; ++c) {
                const float mean =
                    sums[static_cast<std::size_t>(x) * 3 + (channels == 1 ? 0 : c)] / n;
                line[x * 3 + c] =
                    static_cast<uchar>(std::lround(std::clamp(mean, 0.0f, 1.0f) * 255.0f));
            }
        }
    }
    return out;
}

} // namespace

QImage toQImage(const Image& image, int maxSide) {
    const int channels = image.channels >= 3 ? 3 : 1;
    return downsample(image.width, image.height, channels, maxSide,
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

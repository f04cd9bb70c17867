#include "parallax/bake/NormalMapBaker.h"

#include "bake/BakeProgress.h"

#include <array>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <vector>

namespace px {
namespace {

constexpr std::array<std::string_view, 3> kFilterNames{"central", "sobel", "scharr"};

// Weights of the rows (or columns) across the derivative direction; they sum to 1, so each
// filter is an average of central differences and exact on a ramp.
std::array<float, 3> crossWeights(NormalFilter filter) {
    switch (filter) {
    case NormalFilter::Central:
        return {0.0f, 1.0f, 0.0f};
    case NormalFilter::Sobel:
        return {0.25f, 0.5f, 0.25f};
    case NormalFilter::Scharr:
        return {3.0f / 16.0f, 10.0f / 16.0f, 3.0f / 16.0f};
    }
    return {0.0f, 1.0f, 0.0f};
}

// The taps of a central difference along one axis of `size` texels: the lower and upper
// neighbour and 1 / their distance in uv units (0 where there is no neighbour, as on a 1-texel
// side with clamp, or where both taps wrap to one texel).
struct Taps {
    std::vector<int> lo, hi;
    std::vector<float> scale;
};

Taps differenceTaps(int size, WrapMode wrap) {
    Taps t;
    t.lo.resize(size);
    t.hi.resize(size);
    t.scale.resize(size);
    for (int i = 0; i < size; ++i) {
        t.lo[i] = wrapIndex(i - 1, size, wrap);
        t.hi[i] = wrapIndex(i + 1, size, wrap);
        // With repeat the taps are 2 texels apart even when they wrap onto one texel (a period
        // of 2 or 1 has a zero central difference); with clamp, the distance actually spanned.
        const int span =
            wrap == WrapMode::Repeat ? 2 : (std::min(i + 1, size - 1) - std::max(i - 1, 0));
        t.scale[i] = span > 0 ? static_cast<float>(size) / static_cast<float>(span) : 0.0f;
    }
    return t;
}

} // namespace

std::string_view toString(NormalFilter filter) {
    return kFilterNames[static_cast<int>(filter)];
}

std::optional<NormalFilter> parseNormalFilter(std::string_view name) {
    for (std::size_t i = 0; i < kFilterNames.size(); ++i) {
        if (kFilterNames[i] == name)
            return static_cast<NormalFilter>(i);
    }
    return std::nullopt;
}

std::span<const std::string_view> normalFilterNames() {
    return kFilterNames;
}

Result<Image> bakeNormalMap(const HeightField& field, const NormalBakeOptions& options,
                            const BakeControl& control) {
    if (field.empty())
        return Error{"the height map is empty"};
    if (!std::isfinite(options.heightScale) || options.heightScale < 0.0f)
        return Error{"the height scale must be a finite number >= 0"};

    const int W = field.width, H = field.height;
    const Taps tx = differenceTaps(W, options.wrap);
    const Taps ty = differenceTaps(H, options.wrap);
    const std::array<float, 3> w = crossWeights(options.filter);
    const float s = options.heightScale;
    const float greenSign = options.green == NormalGreen::OpenGL ? 1.0f : -1.0f;

    Image out(W, H, 3);
    BakeProgress progress(control, H);
    const float* h = field.texels.data();
    const ImageWriter put = out.writer(); // before the threads: SharedTexels.h
    tbb::parallel_for(tbb::blocked_range<int>(0, H, 16), [&](const tbb::blocked_range<int>& rows) {
        if (progress.stopRequested())
            return;
        for (int y = rows.begin(); y < rows.end(); ++y) {
            // Rows above, at and below y (for dh/du), and the two rows dh/dv differences.
            const float* row[3] = {h + static_cast<std::size_t>(ty.lo[y]) * W,
                                   h + static_cast<std::size_t>(y) * W,
                                   h + static_cast<std::size_t>(ty.hi[y]) * W};
            const float sy = ty.scale[y];
            float* o = &put.at(0, y);
            for (int x = 0; x < W; ++x) {
                const int xl = tx.lo[x], xh = tx.hi[x];
                float du = 0.0f, dv = 0.0f;
                const int cols[3] = {xl, x, xh};
                for (int k = 0; k < 3; ++k) {
                    du += w[k] * (row[k][xh] - row[k][xl]);
                    dv += w[k] * (row[2][cols[k]] - row[0][cols[k]]);
                }
                du *= tx.scale[x];
                dv *= sy;
                const float nx = -s * du, ny = s * dv * greenSign;
                const float inv = 1.0f / std::sqrt(nx * nx + ny * ny + 1.0f);
                o[0] = nx * inv * 0.5f + 0.5f;
                o[1] = ny * inv * 0.5f + 0.5f;
                o[2] = inv * 0.5f + 0.5f;
                o += 3;
            }
        }
        progress.advance(rows.size());
    });
    if (progress.stopRequested())
        return cancelledError();
    progress.finish();
    return out;
}

} // namespace px

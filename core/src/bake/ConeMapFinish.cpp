// What every cone map goes through after its bake: the 3x3 minimum and quantisation.

#include "parallax/bake/ConeMapFinish.h"

#include <algorithm>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <vector>

namespace px {

void applyNeighbourhoodMinimum(ConeMap& cones, WrapMode wrap) {
    const int W = cones.width, H = cones.height;
    if (W <= 0 || H <= 0)
        return;
    // Made the map's own once, before the threads (SharedTexels.h).
    const PlaneWriter g = cones.writer();
    // The minimum is separable: rows first, each from a copy of itself ...
    tbb::parallel_for(tbb::blocked_range<int>(0, H, 16), [&](const tbb::blocked_range<int>& rows) {
        std::vector<float> row(W);
        for (int y = rows.begin(); y < rows.end(); ++y) {
            std::copy_n(&g.at(0, y), W, row.begin());
            for (int x = 0; x < W; ++x)
                g.at(x, y) = std::min(
                    {row[wrapIndex(x - 1, W, wrap)], row[x], row[wrapIndex(x + 1, W, wrap)]});
        }
    });
    // ... then columns, in strips, keeping the unmodified previous row and (repeat) first row.
    constexpr int kStrip = 64;
    auto columns = [&](const tbb::blocked_range<int>& strips) {
        std::vector<float> previous(kStrip), current(kStrip), first(kStrip);
        for (int s = strips.begin(); s < strips.end(); ++s) {
            const int x0 = s * kStrip, n = std::min(kStrip, W - x0);
            std::copy_n(&g.at(x0, wrapIndex(-1, H, wrap)), n, previous.begin());
            std::copy_n(&g.at(x0, 0), n, first.begin());
            for (int y = 0; y < H; ++y) {
                std::copy_n(&g.at(x0, y), n, current.begin());
                const bool last = y + 1 == H;
                const float* next =
                    !last ? &g.at(x0, y + 1)
                          : (wrap == WrapMode::Repeat ? first.data() : current.data());
                float* out = &g.at(x0, y);
                for (int i = 0; i < n; ++i)
                    out[i] = std::min({previous[i], current[i], next[i]});
                std::swap(previous, current);
            }
        }
    };
    tbb::parallel_for(tbb::blocked_range<int>(0, (W + kStrip - 1) / kStrip), columns);
}

void quantiseDown(ConeMap& cones, int levels) {
    const float scale = static_cast<float>(levels);
    for (float& g : cones.sqrtRatio) {
        const float clamped = std::clamp(g, 0.0f, 1.0f);
        float steps = std::floor(clamped * scale);
        if (steps > 0.0f && steps / scale > clamped) // the product rounded up onto a step
            steps -= 1.0f;
        g = steps / scale;
    }
}

} // namespace px

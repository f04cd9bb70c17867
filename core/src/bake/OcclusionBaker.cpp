#include "parallax/bake/OcclusionBaker.h"

#include "bake/BakeProgress.h"
#include "bake/OcclusionHorizon.h"
#include "bake/OcclusionIntegral.h"

#include <atomic>
#include <cmath>
#include <numbers>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <vector>

namespace px {
namespace {

// A horizon counts only this far (relative) above the normal's own: the cell's slope and the
// central difference round differently on a plane, which must stay unoccluded.
constexpr double kPlaneMargin = 1.0 / 1048576.0;

struct Azimuth {
    double cosine, sine;
};

// Evenly spaced, the first along +X; the axes exactly (so rays along texel lines stay on them).
std::vector<Azimuth> azimuths(int count) {
    std::vector<Azimuth> result(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / count;
        double c = std::cos(phi), s = std::sin(phi);
        if ((4 * k) % count == 0) {
            c = std::round(c);
            s = std::round(s);
        }
        result[static_cast<std::size_t>(k)] = {c, s};
    }
    return result;
}

// The central difference along one axis of `size` texels at i, per uv: as the normal bake's
// central filter (clamp: the taps inside the map over their real distance).
double centralDifference(double lo, double hi, int i, int size, WrapMode wrap) {
    const int span =
        wrap == WrapMode::Repeat ? 2 : (std::min(i + 1, size - 1) - std::max(i - 1, 0));
    return span > 0 ? (hi - lo) * size / span : 0.0;
}

} // namespace

int occlusionDirections(const OcclusionBakeOptions& options) {
    return options.directions == 0 ? kDefaultOcclusionDirections : options.directions;
}

Result<OcclusionMaps> bakeOcclusion(const HeightField& field, const OcclusionBakeOptions& options,
                                    OcclusionOutputs outputs, const BakeControl& control) {
    if (field.empty())
        return Error{"the height map is empty"};
    if (!std::isfinite(options.heightScale) || options.heightScale < 0.0f)
        return Error{"the height scale must be a finite number >= 0"};
    if (!(options.distance > 0.0))
        return Error{"the occlusion distance must be > 0 (or inf)"};
    if (options.directions < 0 || options.directions > kMaxOcclusionDirections)
        return Error{"the number of directions must be 0 (the default) to " +
                     std::to_string(kMaxOcclusionDirections)};

    const int W = field.width, H = field.height;
    const double s = options.heightScale;
    const WrapMode wrap = options.wrap;
    const int count = occlusionDirections(options);
    const std::vector<Azimuth> dirs = azimuths(count);
    const occlusion::HorizonSearch search(field, wrap, s, options.distance);

    const bool wantAo = outputs != OcclusionOutputs::BentNormals;
    const bool wantBent = outputs != OcclusionOutputs::AmbientOcclusion;
    OcclusionMaps maps;
    if (wantAo)
        maps.occlusion = Image(W, H, 1);
    if (wantBent)
        maps.bentNormals = Image(W, H, 3);
    const ImageWriter ao = wantAo ? maps.occlusion.writer() : ImageWriter{};
    const ImageWriter bent = wantBent ? maps.bentNormals.writer() : ImageWriter{};
    const double green = options.green == NormalGreen::DirectX ? -1.0 : 1.0;

    BakeProgress progress(control, H);
    std::atomic<bool> stopped{false};
    tbb::parallel_for(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y) {
            if (stopped.load(std::memory_order_relaxed))
                return;
            const int yUp = wrapIndex(y - 1, H, wrap), yDown = wrapIndex(y + 1, H, wrap);
            // Per azimuth, where the previous texel's horizon was: tried first by the next.
            std::vector<double> witness(dirs.size(), 0.0);
            for (int x = 0; x < W; ++x) {
                const int xl = wrapIndex(x - 1, W, wrap), xr = wrapIndex(x + 1, W, wrap);
                const double gu = centralDifference(field.at(xl, y), field.at(xr, y), x, W, wrap);
                const double gv =
                    centralDifference(field.at(x, yUp), field.at(x, yDown), y, H, wrap);
                // n ∝ (-s dh/du, +s dh/dv, 1) in (X, Y, Z) = (u, -v, up).
                const double len = std::sqrt(s * s * (gu * gu + gv * gv) + 1.0);
                const double nx = -s * gu / len, ny = s * gv / len, nz = 1.0 / len;
                double occluded = 0.0, bx = 0.0, by = 0.0, bz = 0.0;
                for (std::size_t k = 0; k < dirs.size(); ++k) {
                    const Azimuth& d = dirs[k];
                    // The tangent of the elevation where n . w = 0 (the slope of n's plane).
                    const double tNormal = s * (gu * d.cosine - gv * d.sine);
                    const double tHorizon = search.horizon(x, y, d.cosine, d.sine, &witness[k]);
                    if (!(tHorizon > tNormal + kPlaneMargin * (1.0 + std::abs(tNormal))))
                        continue;
                    const double a = nx * d.cosine + ny * d.sine;
                    const occlusion::Occluded o = occlusion::occludedBetween(
                        a, nz, occlusion::elevationOf(tNormal), occlusion::elevationOf(tHorizon));
                    occluded += o.occlusion;
                    bx += o.horizontal * d.cosine;
                    by += o.horizontal * d.sine;
                    bz += o.vertical;
                }
                if (wantAo) {
                    const double value = 1.0 - 2.0 * occluded / count;
                    ao.at(x, y) = static_cast<float>(std::clamp(value, 0.0, 1.0));
                }
                if (wantBent) {
                    // The unoccluded hemisphere gives 2 pi / 3 n; each azimuth weighs 2 pi / N.
                    const double step = 2.0 * std::numbers::pi / count;
                    const double full = 2.0 * std::numbers::pi / 3.0;
                    double vx = full * nx - step * bx, vy = full * ny - step * by,
                           vz = full * nz - step * bz;
                    double vLen = std::sqrt(vx * vx + vy * vy + vz * vz);
                    if (!(vLen > 0.0)) {
                        vx = nx;
                        vy = ny;
                        vz = nz;
                        vLen = 1.0;
                    }
                    bent.at(x, y, 0) = static_cast<float>(vx / vLen * 0.5 + 0.5);
                    bent.at(x, y, 1) = static_cast<float>(green * vy / vLen * 0.5 + 0.5);
                    bent.at(x, y, 2) = static_cast<float>(vz / vLen * 0.5 + 0.5);
                }
            }
            if (!progress.advance(1))
                stopped.store(true, std::memory_order_relaxed);
        }
    });
    if (stopped.load() || control.cancelled())
        return cancelledError();
    progress.finish();
    return maps;
}

} // namespace px

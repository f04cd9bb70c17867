#include "preview/ErrorStats.h"

#include "parallax/eval/HitErrorStats.h"
#include "preview/VisibleRegion.h"

#include <algorithm>
#include <cmath>

namespace px::studio {

SurfaceErrors compareSurfaces(const Image& hits, const Image& exact, int mapWidth, int mapHeight,
                              const VisibleRegion* region) {
    SurfaceErrors out;
    out.width = hits.width;
    out.height = hits.height;
    out.error.assign(static_cast<std::size_t>(hits.width) * hits.height, -1.0f);
    if (hits.width != exact.width || hits.height != exact.height || hits.channels < 4 ||
        exact.channels < 4)
        return out;
    // The bench's statistics (HitErrorStats.h), so the readout and the bench agree on a view.
    HitErrorAccumulator pooled;
    for (int y = 0; y < hits.height; ++y) {
        for (int x = 0; x < hits.width; ++x) {
            const float t = hits.at(x, y, 2), te = exact.at(x, y, 2);
            out.steepPixels += te == kSteepSurfaceT;
            if (!(t >= 0.0f) || !(te >= 0.0f))
                continue;
            if (region && !region->contains(exact.at(x, y, 0), exact.at(x, y, 1))) {
                ++out.offRegionPixels;
                continue;
            }
            const double du = (double(hits.at(x, y, 0)) - exact.at(x, y, 0)) * mapWidth;
            const double dv = (double(hits.at(x, y, 1)) - exact.at(x, y, 1)) * mapHeight;
            const double e = std::hypot(du, dv);
            out.error[static_cast<std::size_t>(y) * hits.width + x] = static_cast<float>(e);
            pooled.addError(e, static_cast<int>(std::lround(hits.at(x, y, 3))));
        }
    }
    const HitErrorStats stats = pooled.stats();
    out.pixels = static_cast<int>(stats.rays);
    out.meanError = stats.meanError;
    out.p99Error = stats.p99Error;
    out.maxError = stats.maxError;
    out.otherSurface = static_cast<int>(stats.wrongSurface);
    out.meanFetches = stats.meanFetches;
    return out;
}

std::span<const HeatStop> heatStops() {
    static const HeatStop stops[] = {{0.0f, QColor(44, 95, 214)},
                                     {0.5f, QColor(63, 179, 79)},
                                     {1.0f, QColor(240, 208, 58)},
                                     {2.0f, QColor(216, 52, 44)}};
    return stops;
}

QImage heatMapImage(const SurfaceErrors& errors) {
    QImage image(errors.width, errors.height, QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    const std::span<const HeatStop> stops = heatStops();
    for (int y = 0; y < errors.height; ++y) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < errors.width; ++x) {
            const float e = errors.error[static_cast<std::size_t>(y) * errors.width + x];
            if (e < 0.0f)
                continue;
            QColor c = stops.back().colour;
            for (std::size_t i = 0; i + 1 < stops.size(); ++i) {
                if (e <= stops[i + 1].texels) {
                    const float t = (e - stops[i].texels) / (stops[i + 1].texels - stops[i].texels);
                    const QColor& a = stops[i].colour;
                    const QColor& b = stops[i + 1].colour;
                    c = QColor::fromRgbF(a.redF() + (b.redF() - a.redF()) * t,
                                         a.greenF() + (b.greenF() - a.greenF()) * t,
                                         a.blueF() + (b.blueF() - a.blueF()) * t);
                    break;
                }
            }
            line[x] = qRgba(c.red(), c.green(), c.blue(), 190);
        }
    }
    return image;
}

} // namespace px::studio

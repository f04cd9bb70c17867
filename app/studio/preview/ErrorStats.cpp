#include "preview/ErrorStats.h"

#include "parallax/eval/HitErrorStats.h"
#include "preview/VisibleRegion.h"

#include <algorithm>
#include <cmath>

namespace px::studio {

namespace {

bool traced(const Image& image, int x, int y) {
    return image.at(x, y, 2) >= 0.0f;
}

double distanceTexels(const Image& a, const Image& b, int x, int y, int mapWidth, int mapHeight) {
    const double du = (double(a.at(x, y, 0)) - b.at(x, y, 0)) * mapWidth;
    const double dv = (double(a.at(x, y, 1)) - b.at(x, y, 1)) * mapHeight;
    return std::hypot(du, dv);
}

bool sameSize(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels >= 4 && b.channels >= 4;
}

ErrorFigures figuresOf(const WeightedErrorStats& s) {
    return {s.meanError, s.p99Error, s.maxError, s.wrongSurfaceShare};
}

} // namespace

double pixelArea(const Image& entry, int x, int y) {
    if (!traced(entry, x, y))
        return 0.0;
    // The uv step to the neighbour nearer in uv along one axis, or none.
    auto step = [&](int dx, int dy, double& du, double& dv) {
        double best = -1.0;
        for (int sign : {1, -1}) {
            const int nx = x + sign * dx, ny = y + sign * dy;
            if (nx < 0 || ny < 0 || nx >= entry.width || ny >= entry.height ||
                !traced(entry, nx, ny))
                continue;
            const double su = sign * (double(entry.at(nx, ny, 0)) - entry.at(x, y, 0));
            const double sv = sign * (double(entry.at(nx, ny, 1)) - entry.at(x, y, 1));
            const double length = std::hypot(su, sv);
            if (best < 0.0 || length < best) {
                best = length;
                du = su;
                dv = sv;
            }
        }
        return best >= 0.0;
    };
    double dudx = 0.0, dvdx = 0.0, dudy = 0.0, dvdy = 0.0;
    if (!step(1, 0, dudx, dvdx) || !step(0, 1, dudy, dvdy))
        return 0.0;
    return std::abs(dudx * dvdy - dudy * dvdx);
}

SurfaceErrors compareSurfaces(const Image& hits, const ReferenceSurfaces& references, int mapWidth,
                              int mapHeight, const VisibleRegion* region) {
    SurfaceErrors out;
    out.width = hits.width;
    out.height = hits.height;
    const std::size_t count = static_cast<std::size_t>(hits.width) * hits.height;
    out.technique.assign(count, -1.0f);
    out.filtering.assign(count, -1.0f);
    const Image* exactPtr = references.exact;
    if (!exactPtr || !sameSize(hits, *exactPtr))
        return out;
    const Image& exact = *exactPtr;
    const Image* footprint = references.footprintExact;
    if (footprint && !sameSize(hits, *footprint))
        return out;
    const Image* entry = references.entry;
    if (entry && !sameSize(hits, *entry))
        entry = nullptr;
    // The bench's statistics, weighted by area (WeightedErrorStats.h); the fetches per pixel.
    WeightedErrorAccumulator technique, filtering;
    HitErrorAccumulator fetches;
    std::vector<double> weights(count, 1.0);
    double weightSum = 0.0;
    int weighed = 0;
    for (int y = 0; y < hits.height; ++y) {
        for (int x = 0; x < hits.width; ++x) {
            const float te = exact.at(x, y, 2);
            out.steepPixels += te == kSteepSurfaceT;
            if (!traced(hits, x, y) || !traced(exact, x, y) ||
                (footprint && !traced(*footprint, x, y)))
                continue;
            if (region && (!region->contains(exact.at(x, y, 0), exact.at(x, y, 1)) ||
                           (footprint &&
                            !region->contains(footprint->at(x, y, 0), footprint->at(x, y, 1))))) {
                ++out.offRegionPixels;
                continue;
            }
            const std::size_t i = static_cast<std::size_t>(y) * hits.width + x;
            const Image& reference = footprint ? *footprint : exact;
            const double e = distanceTexels(hits, reference, x, y, mapWidth, mapHeight);
            const double f =
                footprint ? distanceTexels(*footprint, exact, x, y, mapWidth, mapHeight) : 0.0;
            out.technique[i] = static_cast<float>(e);
            out.filtering[i] = static_cast<float>(f);
            out.otherSurface += e > kWrongSurfaceTexels;
            fetches.addError(0.0, static_cast<int>(std::lround(hits.at(x, y, 3))));
            if (entry) {
                weights[i] = pixelArea(*entry, x, y);
                weightSum += weights[i];
                weighed += weights[i] > 0.0;
            }
            ++out.pixels;
        }
    }
    // A pixel alone (no neighbour on the surface) covers no measurable area: where no pixel
    // does, every pixel weighs the same.
    const bool byArea = entry && weighed > 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (out.technique[i] < 0.0f)
            continue;
        const double w = byArea ? weights[i] : 1.0;
        technique.add(out.technique[i], w);
        filtering.add(out.filtering[i], w);
    }
    out.techniqueError = figuresOf(technique.stats());
    out.filteringError = figuresOf(filtering.stats());
    out.area = byArea ? weightSum : 0.0;
    out.meanFetches = fetches.stats().meanFetches;
    return out;
}

SurfaceErrors compareSurfaces(const Image& hits, const Image& exact, int mapWidth, int mapHeight,
                              const VisibleRegion* region) {
    ReferenceSurfaces references;
    references.exact = &exact;
    return compareSurfaces(hits, references, mapWidth, mapHeight, region);
}

std::span<const HeatStop> heatStops() {
    static const HeatStop stops[] = {{0.0f, QColor(44, 95, 214)},
                                     {0.5f, QColor(63, 179, 79)},
                                     {1.0f, QColor(240, 208, 58)},
                                     {2.0f, QColor(216, 52, 44)}};
    return stops;
}

QImage heatMapImage(const SurfaceErrors& errors, HeatMode mode) {
    QImage image(errors.width, errors.height, QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    const std::span<const HeatStop> stops = heatStops();
    const std::vector<float>& values = errors.errors(mode);
    if (values.size() != static_cast<std::size_t>(errors.width) * errors.height)
        return image;
    for (int y = 0; y < errors.height; ++y) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < errors.width; ++x) {
            const float e = values[static_cast<std::size_t>(y) * errors.width + x];
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

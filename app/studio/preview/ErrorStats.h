#pragma once
// A view's error against the exact intersection, from two surface renders of the same view: each
// pixel holds (u, v, t, fetches) of its hit, t = -1 where no surface was drawn and t = -2 where
// the surface is seen more than 89 degrees from its normal (a mesh's rims: docs/meshes.md). The
// error is the distance between the two hits in texels of the height map (docs/conventions.md
// §5), over the pixels where both traced the surface and the exact hit lies on the surface the
// view shows (VisibleRegion.h).

#include "parallax/image/Image.h"

#include <QColor>
#include <QImage>
#include <span>
#include <vector>

namespace px::studio {

class VisibleRegion;

struct SurfaceErrors {
    int width = 0, height = 0;
    std::vector<float> error; // per pixel, texels; negative: not on the surface
    double meanError = 0.0;
    double p99Error = 0.0; // nearest rank
    double maxError = 0.0; // every pixel: a few pixels on another surface lift the mean over p99
    int otherSurface = 0;  // pixels whose hit is more than kWrongSurfaceTexels from the exact one
    double meanFetches = 0.0;
    int pixels = 0;
    int steepPixels = 0;     // surface seen steeper than 89 degrees: not counted above
    int offRegionPixels = 0; // exact hit off the surface the view shows: not counted above
};

// The surface output's t where the view is steeper than 89 degrees from the normal.
inline constexpr float kSteepSurfaceT = -2.0f;

// `region`: the surface the view shows (null: every exact hit counts).
SurfaceErrors compareSurfaces(const Image& hits, const Image& exact, int mapWidth, int mapHeight,
                              const VisibleRegion* region = nullptr);

// The heat map's colours: blue (0 texels) through green (0.5) and yellow (1) to red (2 or more).
struct HeatStop {
    float texels;
    QColor colour;
};
std::span<const HeatStop> heatStops();

// The error in the heatStops() colours, translucent; clear where there is no surface.
QImage heatMapImage(const SurfaceErrors& errors);

} // namespace px::studio

#pragma once
// A view's error from surface renders of the same view: each pixel holds (u, v, t, fetches) of its
// hit, t = -1 where no surface was drawn and t = -2 where the surface is seen more than 89 degrees
// from its normal (a mesh's rims: docs/meshes.md). Two errors, both in texels of the height map's
// level 0 (docs/conventions.md §5):
// - the technique's: its hit against the exact hit on the surface it marches, the height level of
//   the pixel's footprint (what the artist's settings change);
// - the filtering's: that exact hit against level 0's (what the texture unit's mip choice costs,
//   which no setting of the technique changes).
// Pixels count where every render traced the surface and the exact hits lie on the surface the
// view shows (VisibleRegion.h), each weighted by the texture area it covers, so the figures are
// those of the bench's evenly spread rays (WeightedErrorStats.h), whatever the window's size.

#include "parallax/eval/WeightedErrorStats.h"
#include "parallax/image/Image.h"
#include "preview/HeatMode.h"

#include <QColor>
#include <QImage>
#include <span>
#include <vector>

namespace px::studio {

class VisibleRegion;

struct ErrorFigures {
    double mean = 0.0;
    double p99 = 0.0; // weighted nearest rank
    double max = 0.0; // every pixel: a few pixels on another surface lift the mean over p99
    double otherSurfaceShare = 0.0; // of the area: more than kWrongSurfaceTexels off
};

struct SurfaceErrors {
    int width = 0, height = 0;
    std::vector<float> technique; // per pixel, texels; negative: not counted
    std::vector<float> filtering; // per pixel, texels; negative: not counted
    ErrorFigures techniqueError, filteringError;
    int otherSurface = 0; // pixels whose technique error is over kWrongSurfaceTexels
    double meanFetches = 0.0;
    int pixels = 0;
    double area = 0.0;       // of the texture the counted pixels cover, in tiles
    int steepPixels = 0;     // surface seen steeper than 89 degrees: not counted above
    int offRegionPixels = 0; // exact hit off the surface the view shows: not counted above
    const std::vector<float>& errors(HeatMode mode) const {
        return mode == HeatMode::Filtering ? filtering : technique;
    }
};

// The surface output's t where the view is steeper than 89 degrees from the normal.
inline constexpr float kSteepSurfaceT = -2.0f;

// The renders beside the technique's hits: `exact` (level 0) is always there.
struct ReferenceSurfaces {
    const Image* exact = nullptr;
    // The exact hits on the footprint's level (ShaderOutput::FootprintSurface). Null: the
    // technique is measured against `exact` and the filtering error is 0.
    const Image* footprintExact = nullptr;
    // Each pixel's own uv (the untraced surface): the area weights. Null: every pixel weighs 1.
    const Image* entry = nullptr;
};

// `region`: the surface the view shows (null: every exact hit counts).
SurfaceErrors compareSurfaces(const Image& hits, const ReferenceSurfaces& references, int mapWidth,
                              int mapHeight, const VisibleRegion* region = nullptr);
// As above, against `exact` alone, every pixel weighing 1.
SurfaceErrors compareSurfaces(const Image& hits, const Image& exact, int mapWidth, int mapHeight,
                              const VisibleRegion* region = nullptr);

// The area of the texture (in tiles) pixel (x, y) of an entry render covers: |det| of its uv's
// derivatives, from the neighbour on each axis nearer in uv (a seam's other side is far). 0 where
// no surface was drawn or no neighbour was.
double pixelArea(const Image& entry, int x, int y);

// The heat map's colours: blue (0 texels) through green (0.5) and yellow (1) to red (2 or more).
struct HeatStop {
    float texels;
    QColor colour;
};
std::span<const HeatStop> heatStops();

// The errors in the heatStops() colours, translucent; clear where there is none.
QImage heatMapImage(const SurfaceErrors& errors, HeatMode mode = HeatMode::Technique);

} // namespace px::studio

#pragma once
// Everything one viewport draws: the material and its maps, the viewport's technique, the camera,
// light and mesh, and the overlays. A value: previews compare it with the last one to know what
// to upload again.

#include "model/DocumentState.h"
#include "preview/ViewSettings.h"

namespace px::studio {

struct PreviewScene {
    Material material; // technique and params replaced by the viewport's
    std::shared_ptr<const MaterialAssets> assets;
    ViewQuality quality;
    SharedView view;
    ViewOverlays overlays;
    bool traceable = true; // the maps the technique needs are there
};

// What a viewport measured on its last frame. Errors in texels of the height map's level 0,
// weighted by the texture area each pixel covers (ErrorStats.h).
struct PreviewStats {
    double frameMs = 0.0;         // CPU wall time around the draw and glFinish
    double fetchesPerPixel = 0.0; // mean height fetches over the surface's pixels
    // The technique's own error: its hits against the exact hits on the height level it reads.
    double meanError = 0.0;
    double p99Error = 0.0;
    double maxError = 0.0;
    double otherSurfaceShare = 0.0; // of the area: more than 2 texels off
    int otherSurface = 0;           // pixels on another surface than the exact one
    // The filtering's: the exact hits on that level against those on level 0.
    double filteringMeanError = 0.0;
    double filteringP99Error = 0.0;
    double filteringMaxError = 0.0;
    int pixels = 0;          // pixels the figures are over (0: none measured yet)
    double area = 0.0;       // of the texture they cover, in tiles
    int steepPixels = 0;     // surface seen steeper than 89 degrees, not counted (ErrorStats.h)
    int offRegionPixels = 0; // exact hit off the surface the view shows, not counted
    bool valid = false;
};

} // namespace px::studio

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

// What a viewport measured on its last frame.
struct PreviewStats {
    double frameMs = 0.0;         // CPU wall time around the draw and glFinish
    double fetchesPerPixel = 0.0; // mean height fetches over the surface's pixels
    double meanError = 0.0;       // texels, against the exact intersection, same pixels
    double p99Error = 0.0;
    double maxError = 0.0;
    int otherSurface = 0;    // pixels on another surface than the exact one (> 2 texels off)
    int pixels = 0;          // pixels the figures are over (0: none measured yet)
    int steepPixels = 0;     // surface seen steeper than 89 degrees, not counted (ErrorStats.h)
    int offRegionPixels = 0; // exact hit off the surface the view shows, not counted
    bool valid = false;
};

} // namespace px::studio

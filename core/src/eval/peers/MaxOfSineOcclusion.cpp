// Materialize's AO heuristic: the largest faded sine of the elevation per direction
// (PeerOcclusion.h).

#include "eval/peers/PeerSurface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace px {

Result<Image> maxOfSineOcclusion(const HeightField& field, const PeerSurfaceOptions& surfaceOptions,
                                 const MaxOfSineOptions& o, const BakeControl& control) {
    if (Status s = peers::checkSurface(field, surfaceOptions); !s)
        return s.error();
    if (o.directions < 1 || o.steps < 1 || !(o.reachTexels > 0.0) || !std::isfinite(o.reachTexels))
        return Error{"max-of-sine needs at least one direction and one step and a reach > 0"};
    const peers::PeerSurface surface(field, surfaceOptions);
    const double W = field.width, H = field.height;
    return peers::everyTexel(surface, control, [&](int i, int j) {
        const double z0 = surface.zAt(i, j);
        double occlusion = 0.0;
        for (int k = 0; k < o.directions; ++k) {
            const double phi = 2.0 * std::numbers::pi * k / o.directions;
            const double cx = std::cos(phi), cy = -std::sin(phi); // texels, y down the image
            const double uvPerTexel = std::hypot(cx / W, cy / H);
            double strongest = 0.0;
            for (int step = 1; step <= o.steps; ++step) {
                const double texels = o.reachTexels * step / o.steps;
                const double r = texels * uvPerTexel;
                const double z = surface.z(i + texels * cx, j + texels * cy);
                const double sine = std::sin(std::atan2(z - z0, r));
                strongest = std::max(strongest, sine * std::clamp(0.1 * texels, 0.0, 1.0));
            }
            occlusion += strongest;
        }
        return static_cast<float>(1.0 - occlusion / o.directions);
    });
}

} // namespace px

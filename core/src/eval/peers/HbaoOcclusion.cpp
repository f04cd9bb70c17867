// Horizon-based AO as the peers' HBAO nodes run it (PeerOcclusion.h).

#include "eval/peers/PeerSurface.h"

#include <cmath>
#include <numbers>

namespace px {

Result<Image> hbaoOcclusion(const HeightField& field, const PeerSurfaceOptions& surfaceOptions,
                            const HbaoOptions& o, const BakeControl& control) {
    if (Status s = peers::checkSurface(field, surfaceOptions); !s)
        return s.error();
    if (o.directions < 1 || o.steps < 1 || !(o.radius > 0.0) || !std::isfinite(o.radius))
        return Error{"HBAO needs at least one direction and one step and a radius > 0"};
    const peers::PeerSurface surface(field, surfaceOptions);
    const double bias = o.angleBiasDeg * std::numbers::pi / 180.0;
    return peers::everyTexel(surface, control, [&](int i, int j) {
        const glm::dvec3 n = surface.normal(i, j);
        const double z0 = surface.zAt(i, j);
        double occlusion = 0.0;
        for (int k = 0; k < o.directions; ++k) {
            const double phi = 2.0 * std::numbers::pi * k / o.directions;
            // The tangent plane's elevation in this azimuth, raised by the bias.
            const double a = n.x * std::cos(phi) + n.y * std::sin(phi);
            double horizon = std::atan2(-a, n.z) + bias;
            double sinHorizon = std::sin(horizon);
            for (int step = 1; step <= o.steps; ++step) {
                const double r = o.radius * step / o.steps;
                const double z = surface.z(i + surface.dx(r, phi), j + surface.dy(r, phi));
                const double elevation = std::atan2(z - z0, r);
                if (elevation <= horizon)
                    continue;
                const double sinElevation = std::sin(elevation);
                const double falloff = 1.0 - (r * r) / (o.radius * o.radius);
                occlusion += falloff * (sinElevation - sinHorizon);
                horizon = elevation;
                sinHorizon = sinElevation;
            }
        }
        return static_cast<float>(1.0 - occlusion / o.directions);
    });
}

} // namespace px

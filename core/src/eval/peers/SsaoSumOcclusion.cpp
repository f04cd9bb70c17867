// AwesomeBump-style AO: a screen-space sum over a grid, no horizons (PeerOcclusion.h).

#include "eval/peers/PeerSurface.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace px {

Result<Image> ssaoSumOcclusion(const HeightField& field, const PeerSurfaceOptions& surfaceOptions,
                               const SsaoSumOptions& o, const BakeControl& control) {
    if (Status s = peers::checkSurface(field, surfaceOptions); !s)
        return s.error();
    if (o.radius < 1 || !(o.spacingTexels > 0.0) || !std::isfinite(o.spacingTexels))
        return Error{"the SSAO sum needs a grid radius >= 1 and a spacing > 0"};
    const peers::PeerSurface surface(field, surfaceOptions);
    const double W = field.width, H = field.height;
    const int samples = (2 * o.radius + 1) * (2 * o.radius + 1) - 1;
    return peers::everyTexel(surface, control, [&](int i, int j) {
        const glm::dvec3 n = surface.normal(i, j);
        const double z0 = surface.zAt(i, j);
        double sum = 0.0;
        for (int b = -o.radius; b <= o.radius; ++b) {
            for (int a = -o.radius; a <= o.radius; ++a) {
                if (a == 0 && b == 0)
                    continue;
                const double x = a * o.spacingTexels, y = b * o.spacingTexels;
                const glm::dvec3 v(x / W, -y / H, surface.z(i + x, j + y) - z0);
                sum += std::max(0.0, glm::dot(n, glm::normalize(v)));
            }
        }
        return static_cast<float>(1.0 - sum / samples);
    });
}

} // namespace px

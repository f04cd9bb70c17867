// A uniform Monte Carlo ray cast, each ray marched over the height field (PeerOcclusion.h).

#include "eval/peers/PeerSurface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <numbers>

namespace px {

namespace {

// A small counter-based generator: the same rays for a texel however the rows are split.
double uniform(std::uint64_t& state) {
    state += 0x9E3779B97F4A7C15ull; // splitmix64
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

} // namespace

Result<Image> rayMarchOcclusion(const HeightField& field, const PeerSurfaceOptions& surfaceOptions,
                                const RayMarchOptions& o, const BakeControl& control) {
    if (Status s = peers::checkSurface(field, surfaceOptions); !s)
        return s.error();
    if (o.rays < 1 || !(o.distance > 0.0) || !(o.stepTexels > 0.0) || !std::isfinite(o.stepTexels))
        return Error{"the ray cast needs at least one ray, a distance > 0 and a step > 0"};
    const peers::PeerSurface surface(field, surfaceOptions);
    const double step = o.stepTexels / std::max(field.width, field.height); // uv
    const double reach = std::min(o.distance, 4.0);
    const auto steps = static_cast<int>(std::floor(reach / step));
    return peers::everyTexel(surface, control, [&](int i, int j) {
        const glm::dvec3 n = surface.normal(i, j);
        // A frame about n.
        const glm::dvec3 t = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, {1, 0, 0})
                                                                : glm::cross(n, {0, 1, 0}));
        const glm::dvec3 b = glm::cross(n, t);
        const double z0 = surface.zAt(i, j);
        std::uint64_t state =
            (static_cast<std::uint64_t>(o.seed) << 40) ^
            (static_cast<std::uint64_t>(j) * static_cast<std::uint64_t>(field.width) + i);
        double visible = 0.0, total = 0.0;
        for (int ray = 0; ray < o.rays; ++ray) {
            const double cosTheta = uniform(state); // uniform over the hemisphere
            const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
            const double psi = 2.0 * std::numbers::pi * uniform(state);
            const glm::dvec3 w =
                sinTheta * std::cos(psi) * t + sinTheta * std::sin(psi) * b + cosTheta * n;
            total += cosTheta;
            const double across = std::hypot(w.x, w.y);
            bool blocked = false;
            if (across > 1e-12) {
                const double rise = w.z / across, phi = std::atan2(w.y, w.x);
                for (int k = 1; k <= steps; ++k) {
                    const double r = k * step; // not summed: no drift over long rays
                    const double zRay = z0 + r * rise;
                    if (zRay > surface.highest())
                        break;
                    if (zRay < surface.z(i + surface.dx(r, phi), j + surface.dy(r, phi))) {
                        blocked = true;
                        break;
                    }
                }
            }
            if (!blocked)
                visible += cosTheta;
        }
        return static_cast<float>(total > 0.0 ? visible / total : 1.0);
    });
}

} // namespace px

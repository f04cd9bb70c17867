#pragma once
// Occlusion ray directions: a Hammersley set of N points mapped to cosine-weighted directions
// (Malley's method: uniform on the disc, lifted to the hemisphere), so every ray carries the same
// weight and the visible fraction is the cosine-weighted visibility of docs/conventions.md §7.
// Each texel shifts the set by its own Cranley-Patterson rotation (a hash of the texel and the
// seed): neighbouring texels see different directions, and the error turns to fine noise instead
// of bands.

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <numbers>
#include <vector>

namespace px::meshbake {

inline float radicalInverse2(std::uint32_t i) {
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
    i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
    i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
    return static_cast<float>(i) * 2.3283064365386963e-10f;
}

inline std::vector<glm::vec2> hammersley(int n) {
    std::vector<glm::vec2> points(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        points[static_cast<std::size_t>(i)] = {(static_cast<float>(i) + 0.5f) /
                                                   static_cast<float>(n),
                                               radicalInverse2(static_cast<std::uint32_t>(i))};
    return points;
}

// A well-mixed 32-bit hash (lowbias32, Chris Wellons).
inline std::uint32_t mix(std::uint32_t x) {
    x ^= x >> 16u;
    x *= 0x7feb352dU;
    x ^= x >> 15u;
    x *= 0x846ca68bU;
    x ^= x >> 16u;
    return x;
}

// The texel's rotation of the unit square, in [0, 1)^2.
inline glm::vec2 texelShift(int x, int y, std::uint32_t seed) {
    const std::uint32_t h = mix(static_cast<std::uint32_t>(x) * 0x9E3779B9u ^
                                mix(static_cast<std::uint32_t>(y) + 0x632BE5ABu * (seed + 1u)));
    return {static_cast<float>(h & 0xFFFFu) / 65536.0f, static_cast<float>(h >> 16u) / 65536.0f};
}

// The cosine-weighted direction of point `p` (shifted by `shift`) about the unit normal n.
inline glm::vec3 cosineDirection(glm::vec2 p, glm::vec2 shift, const glm::vec3& n) {
    const float u1 = p.x + shift.x - std::floor(p.x + shift.x);
    const float u2 = p.y + shift.y - std::floor(p.y + shift.y);
    const float r = std::sqrt(u1), phi = 2.0f * std::numbers::pi_v<float> * u2;
    // An orthonormal frame about n without branches on its direction (Duff et al. 2017).
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
    const glm::vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const glm::vec3 s(b, sign + n.y * n.y * a, -n.y);
    return r * std::cos(phi) * t + r * std::sin(phi) * s + std::sqrt(std::max(0.0f, 1.0f - u1)) * n;
}

} // namespace px::meshbake

#include "OcclusionReference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace px::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The bilinear surface at texel coordinates (X, Y) (texel centres at integers).
double bilinear(const HeightField& f, WrapMode wrap, double X, double Y) {
    const double fx = std::floor(X), fy = std::floor(Y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    const double tx = X - fx, ty = Y - fy;
    const auto at = [&](int i, int j) {
        return static_cast<double>(f.at(wrapIndex(i, f.width, wrap), wrapIndex(j, f.height, wrap)));
    };
    const double top = at(ix, iy) * (1.0 - tx) + at(ix + 1, iy) * tx;
    const double bottom = at(ix, iy + 1) * (1.0 - tx) + at(ix + 1, iy + 1) * tx;
    return top * (1.0 - ty) + bottom * ty;
}

// Distances in [from, to) at which a coordinate starting at p moving d per uv crosses an integer.
void crossings(double p, double d, double from, double to, std::vector<double>& out) {
    if (d == 0.0)
        return;
    const double start = p + d * from;
    double k = d > 0.0 ? std::floor(start) + 1.0 : std::ceil(start) - 1.0;
    for (;;) {
        const double r = (k - p) / d;
        if (r >= to)
            return;
        if (r > from)
            out.push_back(r);
        k += d > 0.0 ? 1.0 : -1.0;
    }
}

// Composite Simpson's rule of f over [a, b].
template <class F> auto simpson(F f, double a, double b) {
    constexpr int n = 256;
    const double h = (b - a) / n;
    auto sum = f(a) + f(b);
    for (int i = 1; i < n; ++i)
        sum = sum + f(a + h * i) * (i % 2 ? 4.0 : 2.0);
    return sum * (h / 3.0);
}

} // namespace

double referenceHorizon(const HeightField& field, const OcclusionReferenceSettings& settings, int x,
                        int y, double phi) {
    const int W = field.width, H = field.height;
    const WrapMode wrap = settings.wrap;
    // Along an axis, exactly (cos(pi / 2) is not 0 in floating point).
    const auto exact = [](double v) { return std::abs(v) < 1e-12 ? 0.0 : v; };
    const double dx = W * exact(std::cos(phi)), dy = -H * exact(std::sin(phi));
    const double s = settings.scale;
    const double zp = s * field.at(x, y);
    const auto g = [&](double r) { return s * bilinear(field, wrap, x + dx * r, y + dy * r) - zp; };
    const bool open = std::isinf(settings.distance);
    double top = 0.0;
    for (float h : field.texels)
        top = std::max(top, static_cast<double>(h));
    top *= s;

    double end = settings.distance;
    if (open && wrap == WrapMode::Clamp) {
        // Beyond the map along every moving axis the surface is constant.
        const auto beyond = [](double p, double d, int n) {
            if (d > 0.0)
                return (n - 1 - p) / d;
            if (d < 0.0)
                return -p / d;
            return 0.0;
        };
        end = std::max(beyond(x, dx, W), beyond(y, dy, H)) + 1e-9;
    } else if (open) {
        end = settings.openReach;
    }
    double best = open ? 0.0 : -kInf;
    // In chunks of 1/4 uv, so that an unlimited search can stop once nothing can rise enough.
    for (int chunk = 0; 0.25 * chunk < end; ++chunk) {
        const double from = 0.25 * chunk;
        if (from > 0.0 && (top - zp) / from <= best)
            break;
        const double to = std::min(from + 0.25, end);
        std::vector<double> rs{from, to};
        crossings(x, dx, from, to, rs);
        crossings(y, dy, from, to, rs);
        std::sort(rs.begin(), rs.end());
        for (std::size_t i = 0; i + 1 < rs.size(); ++i) {
            const double r0 = rs[i], r1 = rs[i + 1], L = r1 - r0;
            if (!(L > 0.0))
                continue;
            const double g0 = g(r0), gm = g(r0 + L / 2.0), g1 = g(r1);
            best = std::max(best, g1 / r1);
            if (L < 1e-9)
                continue;
            // g(r0 + t) = g0 + beta t + gamma t^2 on this piece (one cell: exactly quadratic).
            const double gamma = 2.0 * (g1 - 2.0 * gm + g0) / (L * L);
            const double beta = (g1 - g0) / L - gamma * L;
            if (r0 == 0.0) {
                best = std::max(best, beta); // the r -> 0+ limit (g0 = 0)
                continue;
            }
            best = std::max(best, g0 / r0);
            // d/dr (g / r) = 0: gamma t^2 + 2 gamma r0 t + (beta r0 - g0) = 0.
            if (gamma != 0.0) {
                const double disc = r0 * r0 - (beta * r0 - g0) / gamma;
                if (disc >= 0.0) {
                    for (double t : {-r0 + std::sqrt(disc), -r0 - std::sqrt(disc)}) {
                        if (t > 0.0 && t < L)
                            best = std::max(best, g(r0 + t) / (r0 + t));
                    }
                }
            }
        }
    }
    return best;
}

ReferenceOcclusion referenceOcclusion(const HeightField& field,
                                      const OcclusionReferenceSettings& settings, int x, int y) {
    const int W = field.width, H = field.height;
    const WrapMode wrap = settings.wrap;
    const auto h = [&](int i, int j) {
        return static_cast<double>(field.at(wrapIndex(i, W, wrap), wrapIndex(j, H, wrap)));
    };
    // The central-filter normal (docs/conventions.md §3).
    const auto derivative = [&](int i, int n, double lo, double hi) {
        const int span = wrap == WrapMode::Repeat ? 2 : std::min(i + 1, n - 1) - std::max(i - 1, 0);
        return span > 0 ? (hi - lo) * n / span : 0.0;
    };
    const double gu = derivative(x, W, h(x - 1, y), h(x + 1, y));
    const double gv = derivative(y, H, h(x, y - 1), h(x, y + 1));
    const double s = settings.scale;
    const glm::dvec3 n = glm::normalize(glm::dvec3(-s * gu, s * gv, 1.0));

    double ao = 0.0;
    glm::dvec3 bent(0.0);
    const int N = settings.azimuths;
    for (int k = 0; k < N; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / N;
        const double c = std::cos(phi), sn = std::sin(phi);
        const double a = n.x * c + n.y * sn;
        const double eNormal = std::atan2(-a, n.z);
        const double eHorizon = std::atan(referenceHorizon(field, settings, x, y, phi));
        const double e0 = std::max(eNormal, eHorizon);
        const double half = std::numbers::pi / 2.0;
        ao += simpson([&](double e) { return (a * std::cos(e) + n.z * std::sin(e)) * std::cos(e); },
                      e0, half);
        bent += simpson(
            [&](double e) {
                const glm::dvec3 w(std::cos(e) * c, std::cos(e) * sn, std::sin(e));
                return w * (glm::dot(n, w) * std::cos(e));
            },
            e0, half);
    }
    ReferenceOcclusion result;
    result.ao = ao * (2.0 / N);
    result.bent = glm::length(bent) > 0.0 ? glm::normalize(bent) : n;
    return result;
}

} // namespace px::test

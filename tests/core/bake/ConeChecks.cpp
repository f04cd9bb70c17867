#include "ConeChecks.h"

#include "TestSupport.h"

#include <algorithm>
#include <cmath>

namespace px::test {

ConeCheck checkConservative(const HeightField& f, WrapMode wrap, int bx, int by, double c, int n) {
    ConeCheck check;
    const double hb = f.at(bx, by), hMax = f.maxHeight();
    const double bu = (bx + 0.5) / f.width, bv = (by + 0.5) / f.height;
    if (hb >= hMax)
        return check;
    // Cells within reach: the cone holds no point higher than hMax beyond c (hMax - h_b).
    // Next to the apex, where the steepest secant may be a directional derivative (r -> 0).
    for (int a = 0; a < 256; ++a) {
        const double angle = 2 * M_PI * a / 256, r = 1e-4;
        double u = bu + r * std::cos(angle) / f.width, v = bv + r * std::sin(angle) / f.height;
        if (wrap == WrapMode::Clamp) {
            u = std::clamp(u, 0.5 / f.width, (f.width - 0.5) / f.width);
            v = std::clamp(v, 0.5 / f.height, (f.height - 0.5) / f.height);
        }
        const double h = bilinearHeight(f, wrap, u, v), d = std::hypot(u - bu, v - bv);
        ++check.points;
        if (h > hb && d > 0) {
            check.minRatio = std::min(check.minRatio, d / (h - hb));
            if (h - hb - d / c > 1e-12) {
                ++check.violations;
                check.worst = std::max(check.worst, h - hb - d / c);
            }
        }
    }
    const double reach = c * (hMax - hb);
    const int rx = static_cast<int>(std::ceil(reach * f.width)) + 1;
    const int ry = static_cast<int>(std::ceil(reach * f.height)) + 1;
    for (int oy = -ry; oy <= ry; ++oy) {
        for (int ox = -rx; ox <= rx; ++ox) {
            const int cx = bx + ox, cy = by + oy; // the cell from texel (cx, cy) to (cx+1, cy+1)
            if (wrap == WrapMode::Clamp && (cx < 0 || cy < 0 || cx > std::max(f.width - 2, 0) ||
                                            cy > std::max(f.height - 2, 0)))
                continue;
            for (int j = 0; j <= n; ++j) {
                for (int i = 0; i <= n; ++i) {
                    double u = (cx + 0.5 + static_cast<double>(i) / n) / f.width;
                    double v = (cy + 0.5 + static_cast<double>(j) / n) / f.height;
                    if (wrap == WrapMode::Clamp) { // inside the box of texel centres
                        u = std::min(u, (f.width - 0.5) / f.width);
                        v = std::min(v, (f.height - 0.5) / f.height);
                    }
                    const double h = bilinearHeight(f, wrap, u, v);
                    const double d = std::hypot(u - bu, v - bv);
                    ++check.points;
                    if (h <= hb)
                        continue;
                    check.minRatio = std::min(check.minRatio, d / (h - hb));
                    const double above = h - hb - d / c;
                    if (above > 1e-9) {
                        ++check.violations;
                        check.worst = std::max(check.worst, above);
                    }
                }
            }
        }
    }
    return check;
}

ConeCheck checkRelaxed(const HeightField& f, WrapMode wrap, int bx, int by, double c,
                       double depth) {
    ConeCheck check;
    const double hb = f.at(bx, by);
    const double bu = (bx + 0.5) / f.width, bv = (by + 0.5) / f.height;
    if (hb >= 1.0 || c <= 0.0)
        return check;
    for (int k = 1; k <= 4; ++k) {
        const double z0 = hb + (1.0 - hb) * k / 4.0;
        for (int a = 0; a < 24; ++a) {
            const double angle = 2 * M_PI * (a + 0.37) / 24;
            for (double slope :
                 {0.02, 0.1, 0.3, 1.0, 3.0, 10.0}) { // horizontal uv per unit descent
                // Inside the cone until |P| t = c (z0 - t - h_b).
                const double tEnd = c * (z0 - hb) / (slope + c);
                double inside = 0.0; // deepest point inside the solid so far
                bool left = false;
                double worst = 0.0;
                for (int s = 0; s <= 300; ++s) {
                    const double t = tEnd * s / 300;
                    const double u = bu + std::cos(angle) * slope * t,
                                 v = bv + std::sin(angle) * slope * t;
                    const double fval = bilinearHeight(f, wrap, u, v) - (z0 - t);
                    inside = std::max(inside, fval);
                    const double exit = std::min(inside, -fval);
                    if (exit > depth) {
                        left = true;
                        worst = std::max(worst, exit);
                    }
                }
                ++check.points;
                if (left) {
                    ++check.violations;
                    check.worst = std::max(check.worst, worst);
                }
            }
        }
    }
    return check;
}

ConeMap bakeRelaxedConesGpuGems(const HeightField& f, int steps) {
    ConeMap cones(ConeKind::Relaxed, f.width, f.height);
    auto depthAt = [&](double u, double v) { // point sampling, repeat, depth = 1 - h
        const int x = static_cast<int>(std::floor(u * f.width)),
                  y = static_cast<int>(std::floor(v * f.height));
        return 1.0 - f.at(wrapIndex(x, f.width, WrapMode::Repeat),
                          wrapIndex(y, f.height, WrapMode::Repeat));
    };
    for (int by = 0; by < f.height; ++by) {
        for (int bx = 0; bx < f.width; ++bx) {
            const double su = (bx + 0.5) / f.width, sv = (by + 0.5) / f.height;
            const double srcDepth = 1.0 - f.at(bx, by);
            double best = 1.0;
            for (int oy = -f.height / 2; oy < f.height - f.height / 2; ++oy) {
                for (int ox = -f.width / 2; ox < f.width - f.width / 2; ++ox) {
                    if (ox == 0 && oy == 0)
                        continue;
                    const double du = su + static_cast<double>(ox) / f.width,
                                 dv = sv + static_cast<double>(oy) / f.height;
                    const double dstDepth = depthAt(du, dv);
                    if (dstDepth >= srcDepth || dstDepth <= 0.0)
                        continue; // only texels higher than b limit the cone
                    // The ray from (b, depth 0) through (d, depth_d), continued to depth 1.
                    double vx = (du - su) / dstDepth, vy = (dv - sv) / dstDepth;
                    const double scale = 1.0 - dstDepth;
                    vx *= scale;
                    vy *= scale;
                    const double sx = vx / steps, sy = vy / steps, sz = scale / steps;
                    double px = du + sx, py = dv + sy, pz = dstDepth + sz;
                    for (int i = 1; i < steps; ++i) {
                        if (depthAt(px, py) <= pz) { // still inside the solid
                            px += sx;
                            py += sy;
                            pz += sz;
                        }
                    }
                    const double ratio =
                        pz >= srcDepth ? 1.0 : std::hypot(px - su, py - sv) / (srcDepth - pz);
                    best = std::min(best, ratio);
                }
            }
            cones.g(bx, by) = static_cast<float>(std::sqrt(std::clamp(best, 0.0, 1.0)));
        }
    }
    return cones;
}

} // namespace px::test

#include "parallax/bake/ConeMapReference.h"

#include <algorithm>
#include <cmath>

namespace px {
namespace {

struct Corners {
    float h00, h10, h01, h11;
};

// Corners of the cell whose top-left texel is (x, y), in wrap/clamp terms.
Corners cellCorners(const HeightField& f, int x, int y, WrapMode wrap) {
    const int x0 = wrapIndex(x, f.width, wrap), x1 = wrapIndex(x + 1, f.width, wrap);
    const int y0 = wrapIndex(y, f.height, wrap), y1 = wrapIndex(y + 1, f.height, wrap);
    return {f.at(x0, y0), f.at(x1, y0), f.at(x0, y1), f.at(x1, y1)};
}

// Steepest slope of a bilinear patch in height per uv: |grad h|^2 is convex, so a corner.
float maxSlope(const Corners& c, float w, float h) {
    const float k = c.h00 - c.h10 - c.h01 + c.h11;
    float best = 0.0f;
    for (int cy = 0; cy < 2; ++cy) {
        for (int cx = 0; cx < 2; ++cx) {
            const float gx = (c.h10 - c.h00 + k * cy) * w;
            const float gy = (c.h01 - c.h00 + k * cx) * h;
            best = std::max(best, std::sqrt(gx * gx + gy * gy));
        }
    }
    return best;
}

// Offsets of cells (relative to the apex texel) to visit: with repeat one period around the apex,
// with clamp only cells inside the map (the border strips only repeat edge heights, farther away).
struct CellRange {
    int lo, hi; // inclusive offsets of the cell's top-left texel
};

CellRange cellRange(int b, int size, WrapMode wrap) {
    if (wrap == WrapMode::Repeat)
        return {-size / 2 - 1, size - size / 2};
    return {-b, size - 2 - b};
}

} // namespace

ConeMap bakeConservativeConesBruteForce(const HeightField& field, WrapMode wrap) {
    ConeMap cones(ConeKind::Conservative, field.width, field.height);
    const float w = static_cast<float>(field.width);
    const float h = static_cast<float>(field.height);
    for (int by = 0; by < field.height; ++by) {
        for (int bx = 0; bx < field.width; ++bx) {
            const float hb = field.at(bx, by);
            float c = 1.0f;
            const CellRange rx = cellRange(bx, field.width, wrap);
            const CellRange ry = cellRange(by, field.height, wrap);
            for (int oy = ry.lo; oy <= ry.hi; ++oy) {
                for (int ox = rx.lo; ox <= rx.hi; ++ox) {
                    const Corners k = cellCorners(field, bx + ox, by + oy, wrap);
                    const float m = std::max({k.h00, k.h10, k.h01, k.h11});
                    if (m <= hb)
                        continue;
                    // Nearest point of the cell [ox, ox+1] x [oy, oy+1] (texel units) to the apex.
                    const float dx = std::max({0.0f, static_cast<float>(ox), -static_cast<float>(ox + 1)});
                    const float dy = std::max({0.0f, static_cast<float>(oy), -static_cast<float>(oy + 1)});
                    const float dist = std::sqrt((dx / w) * (dx / w) + (dy / h) * (dy / h));
                    float bound = dist / (m - hb);
                    const bool touchesApex = ox >= -1 && ox <= 0 && oy >= -1 && oy <= 0;
                    if (touchesApex) {
                        const float slope = maxSlope(k, w, h);
                        bound = slope > 0.0f ? 1.0f / slope : 1.0f;
                    }
                    c = std::min(c, bound);
                }
            }
            cones.g(bx, by) = std::sqrt(std::clamp(c, 0.0f, 1.0f));
        }
    }
    return cones;
}

ConeMap bakeRelaxedConesBruteForce(const HeightField& field, WrapMode wrap) {
    ConeMap cones(ConeKind::Relaxed, field.width, field.height);
    const float w = static_cast<float>(field.width);
    const float h = static_cast<float>(field.height);
    for (int by = 0; by < field.height; ++by) {
        for (int bx = 0; bx < field.width; ++bx) {
            const float hb = field.at(bx, by);
            float c = 1.0f;
            const CellRange rx = cellRange(bx, field.width, wrap);
            const CellRange ry = cellRange(by, field.height, wrap);
            // Every texel d (offset ox, oy) with each cell that lies beyond it, away from b.
            for (int oy = ry.lo; oy <= ry.hi + 1; ++oy) {
                for (int ox = rx.lo; ox <= rx.hi + 1; ++ox) {
                    if (ox == 0 && oy == 0)
                        continue;
                    const int dxI = bx + ox, dyI = by + oy;
                    if (wrap == WrapMode::Clamp &&
                        (dxI < 0 || dyI < 0 || dxI >= field.width || dyI >= field.height))
                        continue;
                    const float hd = field.at(wrapIndex(dxI, field.width, wrap),
                                              wrapIndex(dyI, field.height, wrap));
                    const float dh = hd - hb;
                    const float dist = std::sqrt((ox / w) * (ox / w) + (oy / h) * (oy / h));
                    if (dh <= 0.0f || dist >= c * dh)
                        continue;
                    for (int sy = -1; sy <= 1; sy += 2) {
                        for (int sx = -1; sx <= 1; sx += 2) {
                            if ((ox != 0 && (ox > 0) != (sx > 0)) || (oy != 0 && (oy > 0) != (sy > 0)))
                                continue; // the cell must lie in d's quadrant, away from b
                            const int ex = dxI + sx, ey = dyI + sy;
                            if (wrap == WrapMode::Clamp &&
                                (ex < 0 || ey < 0 || ex >= field.width || ey >= field.height))
                                continue;
                            auto at = [&](int x, int y) {
                                return field.at(wrapIndex(x, field.width, wrap),
                                                wrapIndex(y, field.height, wrap));
                            };
                            const float a = at(dxI, dyI), bX = at(ex, dyI), bY = at(dxI, ey),
                                        d2 = at(ex, ey);
                            const bool falling = bX < a || bY < a || d2 < bX || d2 < bY;
                            if (falling)
                                c = dist / dh;
                        }
                    }
                }
            }
            cones.g(bx, by) = std::sqrt(std::clamp(c, 0.0f, 1.0f));
        }
    }
    return cones;
}

void applyNeighbourhoodMinimum(ConeMap& cones, WrapMode wrap) {
    const ConeMap source = cones;
    for (int y = 0; y < cones.height; ++y) {
        for (int x = 0; x < cones.width; ++x) {
            float m = source.g(x, y);
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx)
                    m = std::min(m, source.g(wrapIndex(x + dx, cones.width, wrap),
                                             wrapIndex(y + dy, cones.height, wrap)));
            }
            cones.g(x, y) = m;
        }
    }
}

void quantiseDown(ConeMap& cones, int levels) {
    const float scale = static_cast<float>(levels);
    for (float& g : cones.sqrtRatio)
        g = std::floor(std::clamp(g, 0.0f, 1.0f) * scale) / scale;
}

} // namespace px

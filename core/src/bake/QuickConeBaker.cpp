// Quick cone maps (Valasek & Bán 2022, docs/cone-maps.md §2) for the bilinear surface: per texel,
// 3x3 blocks of max-pyramid nodes around it, level by level, each node bounded by its maximum at
// the nearest point not already checked (region growing). Θ(N² log N), conservative because
// every cell meets a node whose maximum is at least its own, no nearer than it.

#include "bake/BakeProgress.h"
#include "bake/CellPyramid.h"
#include "parallax/bake/ConeMapBaker.h"

#include <limits>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px {
namespace {

using namespace cone;

constexpr float kFar = std::numeric_limits<float>::infinity();

// A rectangle in texel units relative to the apex.
struct Rect {
    float x0, x1, y0, y1;
};

// Distance from the apex to the nearest point of n outside c (c holds the apex): n minus c is
// covered by n clipped to the four half-planes outside c's sides.
float gapOutside(const Rect& n, const Rect& c, const CellGrid& g) {
    float best = kFar;
    const float nx = gap(n.x0, n.x1), ny = gap(n.y0, n.y1);
    if (n.x0 < c.x0)
        best = std::min(best, texelDistance(gap(n.x0, std::min(n.x1, c.x0)), ny, g));
    if (n.x1 > c.x1)
        best = std::min(best, texelDistance(gap(std::max(n.x0, c.x1), n.x1), ny, g));
    if (n.y0 < c.y0)
        best = std::min(best, texelDistance(nx, gap(n.y0, std::min(n.y1, c.y0)), g));
    if (n.y1 > c.y1)
        best = std::min(best, texelDistance(nx, gap(std::max(n.y0, c.y1), n.y1), g));
    return best;
}

// One axis of the checked block: its cells [first, last] (extended indices with repeat).
struct Span {
    int first, last;
};

class QuickCone {
public:
    QuickCone(const CellGrid& grid, const CellPyramid& pyramid, float heightMax)
        : g(grid), p(pyramid), hMax(heightMax) {}

    float operator()(int bx, int by) const {
        const Apex b{bx, by, g.field->at(bx, by)};
        if (!(b.h < hMax))
            return 1.0f; // nothing rises above the apex
        float c = 1.0f;
        // Level 0: the 3x3 cells around cell (bx, by); the four with b as a corner exactly (the
        // plain bound would be 0 there), the others by their maximum at their nearest point.
        for (int oy = -1; oy <= 1; ++oy) {
            for (int ox = -1; ox <= 1; ++ox) {
                if (!g.repeat() && (!inside(bx + ox, g.cellsX) || !inside(by + oy, g.cellsY)))
                    continue;
                if (isApexCell(ox, oy, g)) {
                    c = std::min(c, floatDown(apexConservativeBound(g, b, ox, oy, g.shape())));
                    continue;
                }
                const float m = p.at(0, wrapIndex(bx + ox, g.cellsX, g.wrap),
                                     wrapIndex(by + oy, g.cellsY, g.wrap));
                if (m > b.h)
                    c = std::min(
                        c, texelDistance(gap(ox, ox + g.spanX()), gap(oy, oy + g.spanY()), g) /
                               (m - b.h));
            }
        }
        Span sx = clip({bx - 1, bx + 1}, g.cellsX), sy = clip({by - 1, by + 1}, g.cellsY);
        for (int level = 1; level < p.levels() && !done(b, sx, sy, c); ++level) {
            const int nx = p.width(level), ny = p.height(level);
            const int ax = bx >> level, ay = by >> level;
            const Rect checked = rect(sx, sy, b);
            for (int ey = ay - 1; ey <= ay + 1; ++ey) {
                if (!g.repeat() && !inside(ey, ny))
                    continue;
                for (int ex = ax - 1; ex <= ax + 1; ++ex) {
                    if ((ex == ax && ey == ay) || (!g.repeat() && !inside(ex, nx)))
                        continue; // the centre node lies inside the previous block
                    const float m =
                        p.at(level, ex - floorDiv(ex, nx) * nx, ey - floorDiv(ey, ny) * ny);
                    if (!(m > b.h))
                        continue;
                    const CellRange cx = nodeCells(ex, level, nx, g.cellsX);
                    const CellRange cy = nodeCells(ey, level, ny, g.cellsY);
                    const float d =
                        gapOutside(rect({cx.first, cx.last}, {cy.first, cy.last}, b), checked, g);
                    if (d < kFar)
                        c = std::min(c, d / (m - b.h));
                }
            }
            sx = blockSpan(ax, level, nx, g.cellsX);
            sy = blockSpan(ay, level, ny, g.cellsY);
        }
        return c;
    }

private:
    static bool inside(int i, int n) { return i >= 0 && i < n; }

    Span clip(Span s, int cells) const {
        if (g.repeat())
            return s;
        return {std::max(s.first, 0), std::min(s.last, cells - 1)};
    }

    // The cells of nodes a-1 .. a+1 at `level`.
    Span blockSpan(int a, int level, int nodes, int cells) const {
        int lo = a - 1, hi = a + 1;
        if (!g.repeat()) {
            lo = std::max(lo, 0);
            hi = std::min(hi, nodes - 1);
        }
        return {nodeCells(lo, level, nodes, cells).first, nodeCells(hi, level, nodes, cells).last};
    }

    Rect rect(Span x, Span y, const Apex& b) const {
        return {static_cast<float>(x.first - b.x), static_cast<float>(x.last + g.spanX() - b.x),
                static_cast<float>(y.first - b.y), static_cast<float>(y.last + g.spanY() - b.y)};
    }

    // Early stop: every cell outside the checked block is at least `d` away and at most hMax
    // high, so it cannot narrow the cone once d / (hMax - h_b) >= c. With clamp a side at the
    // map's edge has nothing beyond it.
    bool done(const Apex& b, Span sx, Span sy, float c) const {
        float d = kFar;
        if (g.repeat() || sx.first > 0)
            d = std::min(d, texelDistance(static_cast<float>(b.x - sx.first), 0.0f, g));
        if (g.repeat() || sx.last < g.cellsX - 1)
            d = std::min(d, texelDistance(static_cast<float>(sx.last + 1 - b.x), 0.0f, g));
        if (g.repeat() || sy.first > 0)
            d = std::min(d, texelDistance(0.0f, static_cast<float>(b.y - sy.first), g));
        if (g.repeat() || sy.last < g.cellsY - 1)
            d = std::min(d, texelDistance(0.0f, static_cast<float>(sy.last + 1 - b.y), g));
        return d == kFar || d / (hMax - b.h) >= c;
    }

    const CellGrid& g;
    const CellPyramid& p;
    float hMax;
};

} // namespace

Result<ConeMap> bakeQuickConeMap(const HeightField& field, WrapMode wrap,
                                 const BakeControl& control) {
    if (field.empty())
        return Error{"the height map is empty"};
    const CellGrid grid(field, wrap);
    const CellPyramid pyramid(grid);
    const QuickCone cone(grid, pyramid, field.maxHeight());
    ConeMap cones(ConeKind::Conservative, field.width, field.height);
    BakeProgress progress(control, field.height);
    tbb::parallel_for(tbb::blocked_range<int>(0, field.height, 2),
                      [&](const tbb::blocked_range<int>& rows) {
                          if (progress.stopRequested())
                              return;
                          for (int y = rows.begin(); y < rows.end(); ++y) {
                              for (int x = 0; x < field.width; ++x)
                                  cones.g(x, y) = std::sqrt(finishRatio(cone(x, y)));
                          }
                          progress.advance(rows.size());
                      });
    if (progress.stopRequested())
        return cancelledError();
    progress.finish();
    return cones;
}

} // namespace px

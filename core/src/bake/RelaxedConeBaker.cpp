// Relaxed cone maps, safe for the bilinear surface (CONE_MAPS.md §1, Bán et al. 2024): per texel
// the ring scan's cells, found by a branch and bound over a maximum pyramid of the cells that can
// fall away from the apex (per direction sector, SectorPyramid.h), nearest nodes first; a node is
// skipped whole once its maximum at its nearest point cannot narrow the cone, so the result is
// the brute-force ring scan's (to the per-cell bound's tolerance).

#include "bake/BakeProgress.h"
#include "bake/SectorPyramid.h"
#include "parallax/bake/ConeMapBaker.h"

#include <array>
#include <cstdint>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <vector>

namespace px {
namespace {

using namespace cone;

// Clamp only: the strips beyond the map's edges (ConeCells.h), found through a 1-D maximum
// pyramid of the edge segments per side.
class EdgeStrips {
public:
    explicit EdgeStrips(const CellGrid& g) {
        for (int side = 0; side < 4; ++side) {
            const int n = stripSegments(g, side);
            if (n == 0)
                continue;
            std::vector<float> level(n);
            for (int i = 0; i < n; ++i) {
                int x, y;
                Shape shape;
                stripSegment(g, side, i, x, y, shape);
                level[i] = std::max(g.texel(x, y), g.texel(x + shape.wx, y + shape.wy));
            }
            m_levels[side].push_back(level);
            while (m_levels[side].back().size() > 1) {
                const std::vector<float>& child = m_levels[side].back();
                std::vector<float> parent((child.size() + 1) / 2);
                for (std::size_t i = 0; i < parent.size(); ++i)
                    parent[i] = std::max(child[2 * i], 2 * i + 1 < child.size() ? child[2 * i + 1]
                                                                                : child[2 * i]);
                m_levels[side].push_back(std::move(parent));
            }
        }
    }

    float narrow(const CellGrid& g, const Apex& b, float c) const {
        for (int side = 0; side < 4; ++side) {
            const auto& levels = m_levels[side];
            if (levels.empty())
                continue;
            const int n = static_cast<int>(levels[0].size());
            std::array<std::pair<int, int>, 64> stack; // (level, index)
            int top = 0;
            stack[top++] = {static_cast<int>(levels.size()) - 1, 0};
            while (top > 0) {
                const auto [level, index] = stack[--top];
                if (!(levels[level][index] > b.h))
                    continue;
                const int first = index << level, last = std::min((index + 1) << level, n) - 1;
                int x, y;
                Shape shape;
                stripSegment(g, side, first, x, y, shape);
                const int ox = x - b.x, oy = y - b.y;
                const int lastX = ox + (last - first + 1) * shape.wx,
                          lastY = oy + (last - first + 1) * shape.wy;
                const float u = gap(static_cast<float>(ox), static_cast<float>(lastX)) * g.invW;
                const float v = gap(static_cast<float>(oy), static_cast<float>(lastY)) * g.invH;
                const float rise = levels[level][index] - b.h;
                if (u * u + v * v >= c * c * rise * rise * (1.0f + 1e-5f))
                    continue;
                if (level == 0) {
                    c = relaxedCell(g, b, ox, oy, c, shape);
                    continue;
                }
                for (int k = 1; k >= 0; --k) {
                    if (2 * index + k < static_cast<int>(levels[level - 1].size()))
                        stack[top++] = {level - 1, 2 * index + k};
                }
            }
        }
        return c;
    }

private:
    std::array<std::vector<std::vector<float>>, 4> m_levels;
};

// The cell that limited a neighbouring texel's cone.
struct Witness {
    bool valid = false;
    int x = 0, y = 0;
};

// Nodes one texel's search may open before it settles for node bounds: caps the worst case at
// Θ(N²) per level without touching ordinary maps (a few hundred nodes per texel).
constexpr int kNodeBudget = 4096;

struct Node {
    int level, x, y;  // node of the pyramid
    int baseX, baseY; // its period's first cell, relative to the apex
};

class RelaxedCone {
public:
    RelaxedCone(const CellGrid& grid, const SectorPyramid& pyramid, const EdgeStrips& strips,
                float heightMax)
        : g(grid), p(pyramid), edges(strips), hMax(heightMax) {}

    // The cone at texel (bx, by). `left` and `up` are the cells (absolute, extended) that limited
    // the cones of the texels to the left and above: tried first, they usually set c close to its
    // final value, so the search below skips most nodes. `witness` receives this texel's
    // limiting cell.
    float operator()(int bx, int by, const Witness& left, const Witness& up,
                     Witness& witness) const {
        const Apex b{bx, by, g.field->at(bx, by)};
        if (!(b.h < hMax))
            return 1.0f;
        float c = 1.0f;
        auto visit = [&](int ox, int oy) {
            const float before = c;
            c = relaxedCell(g, b, ox, oy, c);
            if (c < before)
                witness = {true, bx + ox, by + oy};
        };
        witness = {};
        for (const Witness* w : {&left, &up}) {
            if (w->valid && valid(b, w->x - bx, w->y - by))
                visit(w->x - bx, w->y - by);
        }
        // The 3x3 cells around the apex (the four with b as a corner are bounded exactly).
        for (int oy = -1; oy <= 1; ++oy) {
            for (int ox = -1; ox <= 1; ++ox) {
                if (valid(b, ox, oy))
                    visit(ox, oy);
            }
        }
        std::array<Node, 512> stack;
        int top = 0;
        const int topLevel = p.levels() - 1;
        const int periods = g.repeat() ? 1 : 0;
        for (int py = -periods; py <= periods; ++py) {
            for (int px = -periods; px <= periods; ++px) {
                const Node root{topLevel, 0, 0, px * g.cellsX - bx, py * g.cellsY - by};
                if (topLevel == 0 || nodeBound2(root, b, c) < c * c * kMargin)
                    stack[top++] = root;
            }
        }
        int budget = kNodeBudget;
        while (top > 0) {
            const Node n = stack[--top];
            const int x0 = n.baseX + (n.x << n.level);
            const int y0 = n.baseY + (n.y << n.level);
            if (n.level == 0) { // a root of a 1-cell map
                visitCell(n.x, n.y, x0, y0, 0xff, b, c, visit);
                continue;
            }
            if (--budget < 0) {
                // Out of budget (a pathological map): the node's own bound is a valid, looser
                // bound for every cell under it.
                const float bound2 = nodeBound2(n, b, c);
                if (bound2 < c * c * kMargin)
                    c = std::min(c, std::sqrt(bound2) * (1.0f - 1e-5f));
                continue;
            }
            if (n.level == 1) { // its cells, at once
                const int x1 = n.baseX + std::min((n.x + 1) * 2, g.cellsX) - 1;
                const int y1 = n.baseY + std::min((n.y + 1) * 2, g.cellsY) - 1;
                const std::uint8_t sectors = sectorsOf(x0, x1 + g.spanX(), y0, y1 + g.spanY(), g);
                for (int j = 0; j < 2 && 2 * n.y + j < p.height(0); ++j) {
                    for (int i = 0; i < 2 && 2 * n.x + i < p.width(0); ++i)
                        visitCell(2 * n.x + i, 2 * n.y + j, x0 + i, y0 + j, sectors, b, c, visit);
                }
                continue;
            }
            // Children, nearest-bound last so that it is popped first.
            Node children[4];
            float bounds[4];
            int count = 0;
            const int cl = n.level - 1, cw = p.width(cl), ch = p.height(cl);
            for (int j = 0; j < 2; ++j) {
                for (int i = 0; i < 2; ++i) {
                    const Node k{cl, 2 * n.x + i, 2 * n.y + j, n.baseX, n.baseY};
                    if (k.x >= cw || k.y >= ch)
                        continue;
                    const float bound = nodeBound2(k, b, c);
                    if (bound >= c * c * kMargin)
                        continue;
                    int at = count++;
                    for (; at > 0 && bounds[at - 1] < bound; --at) {
                        children[at] = children[at - 1];
                        bounds[at] = bounds[at - 1];
                    }
                    children[at] = k;
                    bounds[at] = bound;
                }
            }
            for (int k = 0; k < count; ++k)
                stack[top++] = children[k];
        }
        return edges.narrow(g, b, c);
    }

private:
    bool valid(const Apex& b, int ox, int oy) const {
        if (g.repeat())
            return !beyondPeriod(g, ox, oy);
        return b.x + ox >= 0 && b.x + ox < g.cellsX && b.y + oy >= 0 && b.y + oy < g.cellsY;
    }

    // A lower bound of every cell bound under the node, squared (>= c^2: skip it). Squares
    // avoid a square root per node; the comparison keeps a margin so that a node is skipped
    // only if its bound certainly is >= c.
    float nodeBound2(const Node& n, const Apex& b, float c) const {
        const int size = 1 << n.level;
        const int x0 = n.baseX + n.x * size, y0 = n.baseY + n.y * size;
        const int x1 = n.baseX + std::min((n.x + 1) * size, g.cellsX) - 1;
        const int y1 = n.baseY + std::min((n.y + 1) * size, g.cellsY) - 1;
        const float m =
            p.maxFalling(n.level, n.x, n.y, sectorsOf(x0, x1 + g.spanX(), y0, y1 + g.spanY(), g));
        const float skip = c * c * kMargin;
        if (!(m > b.h))
            return skip;
        const float gx = gap(static_cast<float>(x0), static_cast<float>(x1 + g.spanX()));
        const float gy = gap(static_cast<float>(y0), static_cast<float>(y1 + g.spanY()));
        if (g.repeat() && (gx >= g.field->width || gy >= g.field->height))
            return skip;
        const float u = gx * g.invW, v = gy * g.invH, rise = m - b.h;
        return (u * u + v * v) / (rise * rise);
    }

    static constexpr float kMargin = 1.0f + 1e-5f;

    // Cell (x, y) of the map at offset (ox, oy), seen within `sectors`: the cheap tests first
    // (not one of the 3x3 already done, can fall in these directions, plain bound below c).
    template <typename Visit>
    void visitCell(int x, int y, int ox, int oy, std::uint8_t sectors, const Apex& b, float c,
                   Visit& visit) const {
        if ((ox >= -1 && ox <= 1 && oy >= -1 && oy <= 1) || beyondPeriod(g, ox, oy))
            return;
        const std::uint8_t falls = p.falls(x, y) & sectors;
        if (falls && mayNarrow(x, y, ox, oy, b, c) &&
            (falls & sectorsOf(ox, ox + g.spanX(), oy, oy + g.spanY(), g)))
            visit(ox, oy);
    }

    // Whether cell (x, y) of the map, at offset (ox, oy), can narrow c by its plain bound: the
    // cheap test before relaxedCell(), with the cell's corners read directly.
    bool mayNarrow(int x, int y, int ox, int oy, const Apex& b, float c) const {
        const HeightField& f = *g.field;
        const int x1 = g.repeat() ? (x + 1 == f.width ? 0 : x + 1) : std::min(x + 1, f.width - 1);
        const int y1 = g.repeat() ? (y + 1 == f.height ? 0 : y + 1) : std::min(y + 1, f.height - 1);
        const float m =
            std::max(std::max(f.at(x, y), f.at(x1, y)), std::max(f.at(x, y1), f.at(x1, y1)));
        if (!(m > b.h))
            return false;
        const float u = gap(static_cast<float>(ox), static_cast<float>(ox + g.spanX())) * g.invW;
        const float v = gap(static_cast<float>(oy), static_cast<float>(oy + g.spanY())) * g.invH;
        const float rise = m - b.h;
        return u * u + v * v < c * c * kMargin * rise * rise;
    }

    const CellGrid& g;
    const SectorPyramid& p;
    const EdgeStrips& edges;
    float hMax;
};

} // namespace

Result<ConeMap> bakeRelaxedConeMap(const HeightField& field, WrapMode wrap,
                                   const BakeControl& control) {
    if (field.empty())
        return Error{"the height map is empty"};
    const CellGrid grid(field, wrap);
    const SectorPyramid pyramid(grid, field.maxHeight());
    const EdgeStrips strips(grid);
    const RelaxedCone cone(grid, pyramid, strips, field.maxHeight());
    ConeMap cones(ConeKind::Relaxed, field.width, field.height);
    BakeProgress progress(control, field.height);
    tbb::parallel_for(
        tbb::blocked_range<int>(0, field.height, 4), [&](const tbb::blocked_range<int>& rows) {
            if (progress.stopRequested())
                return;
            std::vector<Witness> above(field.width), current(field.width);
            for (int y = rows.begin(); y < rows.end(); ++y) {
                for (int x = 0; x < field.width; ++x) {
                    const Witness& left = x > 0 ? current[x - 1] : Witness{};
                    cones.g(x, y) = std::sqrt(finishRatio(cone(x, y, left, above[x], current[x])));
                }
                std::swap(above, current);
            }
            progress.advance(rows.size());
        });
    if (progress.stopRequested())
        return cancelledError();
    progress.finish();
    return cones;
}

} // namespace px

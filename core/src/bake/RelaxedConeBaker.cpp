// Relaxed cone maps, safe for the bilinear surface (docs/cone-maps.md §1, Bán et al. 2024): per
// texel the ring scan's cells, found by a branch and bound over a maximum pyramid of the cells that
// can fall away from the apex (per direction sector, SectorPyramid.h), nearest nodes first; a node
// is skipped once its maximum at its nearest point cannot narrow the cone, so the result is the
// brute-force ring scan's (to the per-cell bound's tolerance). Apexes go in 4x4 tiles that share
// one traversal, each starting from the cells that limited its neighbours' cones.

#include "bake/BakeProgress.h"
#include "bake/EdgeStrips.h"
#include "bake/SectorPyramid.h"
#include "parallax/bake/ConeMapBaker.h"

#include <array>
#include <cstdint>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <vector>

namespace px {
namespace {

using namespace cone;

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
    int baseX, baseY; // its period's first cell (0, or -+ a period with repeat)
};

// A rectangle of texels, inclusive.
struct Box {
    int x0, x1, y0, y1;
};

// A cell of a leaf node: where it is in the node, the sectors it can fall in and its corners.
struct Cell {
    int i, j;
    Sectors falls;
    cone::Corners k;
};

// Apexes searched together: a kTile x kTile block of texels.
constexpr int kTile = 4;

// Tile rows per parallel chunk: at most this many, at least half as many.
constexpr int kChunkRows = 16;

// A tile row's share of the progress bar against one cell row of the set-up.
constexpr int kTileRowWork = 200;

// The apexes of a tile, as arrays: the bounds below loop over them for every node.
struct TileApexes {
    static constexpr int kMax = kTile * kTile;
    int count = 0;
    std::array<Apex, kMax> b;
    std::array<Witness*, kMax> witness;
    // Cone ratios and heights; past `count`, c = 0, so those lanes never reach anything.
    std::array<float, kMax> c{}, h{};

    // The largest c_a (m - h_a) over the apexes, at least 0: in four independent maxima, which
    // the compiler can overlap (the same value: max is exact in any order).
    float reach(float m) const {
        float r[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        for (int k = 0; k < kMax; k += 4) {
            for (int l = 0; l < 4; ++l)
                r[l] = std::max(r[l], c[k + l] * (m - h[k + l]));
        }
        return std::max(std::max(r[0], r[1]), std::max(r[2], r[3]));
    }
};

class RelaxedCone {
public:
    RelaxedCone(const CellGrid& grid, const SectorPyramid& pyramid, const EdgeStrips& strips,
                float heightMax)
        : g(grid), p(pyramid), edges(strips), hMax(heightMax) {}

    // The cones of a tile of texels [tx, tx + tw) x [ty, ty + th), searched together: nodes are
    // opened for the tile as a whole (bounds from the tile's rectangle, lowest apex and widest
    // cone so far), cells tried for each apex. Neighbouring apexes open nearly the same nodes, so
    // the traversal is shared. `witness` holds a witness per texel for rows ty - 1 .. ty + th - 1
    // (row r at (r - ty + 1) * stride): the cells that limited the texels to the left and above
    // are tried first, and usually set each cone close to its final value.
    void tile(int tx, int ty, int tw, int th, Witness* witness, int stride, ConeMap& out) const {
        TileApexes a;
        for (int j = 0; j < th; ++j) {
            for (int i = 0; i < tw; ++i) {
                const int x = tx + i, y = ty + j;
                Witness* w = &witness[(j + 1) * stride + x];
                *w = {};
                const Apex b{x, y, g.field->at(x, y)};
                if (!(b.h < hMax)) {
                    out.g(x, y) = 1.0f; // nothing rises above the apex
                    continue;
                }
                float c = 1.0f;
                const Witness left = i > 0 || x > 0 ? witness[(j + 1) * stride + x - 1] : Witness{};
                const Witness up = witness[j * stride + x];
                for (const Witness& v : {left, up}) {
                    if (v.valid && valid(b, v.x - x, v.y - y))
                        narrow(b, c, w, v.x - x, v.y - y);
                }
                // The 3x3 cells around the apex (the four with b as a corner are exact).
                for (int oy = -1; oy <= 1; ++oy) {
                    for (int ox = -1; ox <= 1; ++ox) {
                        if (valid(b, ox, oy))
                            narrow(b, c, w, ox, oy);
                    }
                }
                const int k = a.count++;
                a.b[k] = b;
                a.witness[k] = w;
                a.c[k] = c;
                a.h[k] = b.h;
            }
        }
        if (a.count > 0)
            search(Box{tx, tx + tw - 1, ty, ty + th - 1}, a);
        for (int k = 0; k < a.count; ++k)
            out.g(a.b[k].x, a.b[k].y) = std::sqrt(finishRatio(edges.narrow(g, a.b[k], a.c[k])));
    }

private:
    // The branch and bound over the pyramid for the apexes of tileBox, nearest nodes first.
    void search(const Box& tileBox, TileApexes& a) const {
        std::array<Node, 512> stack;
        int top = 0;
        const int topLevel = p.levels() - 1;
        const int periods = g.repeat() ? 1 : 0;
        for (int py = -periods; py <= periods; ++py) {
            for (int px = -periods; px <= periods; ++px) {
                const Node root{topLevel, 0, 0, px * g.cellsX, py * g.cellsY};
                if (topLevel == 0 || tileBound(root, tileBox, a) < 1.0f)
                    stack[top++] = root;
            }
        }
        int budget = kNodeBudget * a.count;
        while (top > 0) {
            const Node n = stack[--top];
            if (n.level <= 1) {
                leaf(n, a);
                continue;
            }
            if (--budget < 0) {
                // Out of budget (a pathological map): the node's own bound is a valid, looser
                // bound for every cell under it.
                for (int k = 0; k < a.count; ++k) {
                    TileApexes one;
                    one.count = 1;
                    one.c[0] = a.c[k];
                    one.h[0] = a.h[k];
                    const Apex& b = a.b[k];
                    const float bound = tileBound(n, Box{b.x, b.x, b.y, b.y}, one);
                    if (bound < 1.0f) // the node's bound is below c: c = c sqrt(bound)
                        a.c[k] *= std::sqrt(bound) * (1.0f - 1e-5f);
                }
                continue;
            }
            // Children, nearest-bound last so that it is popped first.
            Node children[4];
            float bounds[4];
            int open = 0;
            const int cl = n.level - 1, cw = p.width(cl), ch = p.height(cl);
            p.prefetch(cl, 2 * n.x, 2 * n.y);
            for (int j = 0; j < 2; ++j) {
                for (int i = 0; i < 2; ++i) {
                    const Node k{cl, 2 * n.x + i, 2 * n.y + j, n.baseX, n.baseY};
                    if (k.x >= cw || k.y >= ch)
                        continue;
                    float bound = 0.0f;
                    if (tileBound(k, tileBox, a, &bound) >= 1.0f)
                        continue;
                    int at = open++;
                    for (; at > 0 && bounds[at - 1] < bound; --at) {
                        children[at] = children[at - 1];
                        bounds[at] = bounds[at - 1];
                    }
                    children[at] = k;
                    bounds[at] = bound;
                }
            }
            for (int k = 0; k < open; ++k)
                stack[top++] = children[k];
        }
    }

    // A leaf node's cells (the node itself for a 1-cell map), for each apex that the node alone
    // may concern.
    void leaf(const Node& n, TileApexes& a) const {
        const int step = n.level == 1 ? 2 : 1;
        // The cells that can fall at all, read once for every apex.
        std::array<Cell, 4> cells;
        int cellCount = 0;
        for (int j = 0; j < step && n.y * step + j < p.height(0); ++j) {
            for (int i = 0; i < step && n.x * step + i < p.width(0); ++i) {
                const int x = n.x * step + i, y = n.y * step + j;
                if (const Sectors falls = p.falls(x, y))
                    cells[cellCount++] = {i, j, falls, corners(x, y)};
            }
        }
        if (cellCount == 0)
            return;
        // A level-0 node is the whole map's one cell: it has no maxima stored.
        const bool test = a.count > 1 && n.level == 1;
        const float mAny = test ? p.maxFalling(n.level, n.x, n.y) : 0.0f;
        for (int k = 0; k < a.count; ++k) {
            const Apex& b = a.b[k];
            const Offsets o = offsets(n, Box{b.x, b.x, b.y, b.y});
            // Most nodes are too far or too low for this apex in any direction.
            if (test && bound(o, a.c[k] * (mAny - b.h)) >= 1.0f)
                continue;
            const Sectors sectors = sectorsOf(o.x0, o.x1, o.y0, o.y1, g);
            if (test && bound(o, a.c[k] * (p.maxFalling(n.level, n.x, n.y, sectors) - b.h)) >= 1.0f)
                continue;
            for (int c = 0; c < cellCount; ++c)
                visitCell(cells[c], o.x0 + cells[c].i, o.y0 + cells[c].j, sectors, b, a.c[k],
                          a.witness[k]);
        }
    }

    bool valid(const Apex& b, int ox, int oy) const {
        if (g.repeat())
            return !beyondPeriod(g, ox, oy);
        return b.x + ox >= 0 && b.x + ox < g.cellsX && b.y + oy >= 0 && b.y + oy < g.cellsY;
    }

    // Whether node n may hold a cell that narrows the cone of one of the apexes in `box`
    // (texels), as a priority (smaller: more promising; >= 1: skip it). The offsets from the box
    // to the node form the rectangle node - box, whose nearest point d and direction sectors hold
    // for every pair; apex a needs d < c_a (m - h_a) for the node's falling maximum m. Squares
    // avoid a square root per node, with a margin so that a node is skipped only if certainly
    // useless. With `order`, also the priority the nodes are opened in: the same bound over the
    // node's 45-degree octants (a coarser sector set), as before there were 16 sectors, so that
    // cells are met in the same order and the cones come out the same (the per-cell bound's
    // tolerance depends on the order).
    float tileBound(const Node& n, const Box& box, const TileApexes& a,
                    float* order = nullptr) const {
        const Offsets o = offsets(n, box);
        // First over all sectors: most nodes are too far or too low in any direction.
        if (bound(o, a.reach(p.maxFalling(n.level, n.x, n.y))) >= 1.0f)
            return kFar;
        const Sectors sectors = sectorsOf(o.x0, o.x1, o.y0, o.y1, g);
        const float m = p.maxFalling(n.level, n.x, n.y, sectors);
        const float b = bound(o, a.reach(m));
        if (order && b < 1.0f) {
            const Sectors rest = octants(sectors) & static_cast<Sectors>(~sectors);
            const float octantMax = std::max(m, p.maxFalling(n.level, n.x, n.y, rest));
            *order = bound(o, a.reach(octantMax));
        }
        return b;
    }

    // The offsets (texels) from the apexes of `box` to the cells of node n, far corners included.
    struct Offsets {
        int x0, x1, y0, y1;
    };
    Offsets offsets(const Node& n, const Box& box) const {
        const int size = 1 << n.level;
        return {n.baseX + n.x * size - box.x1,
                n.baseX + std::min((n.x + 1) * size, g.cellsX) - 1 + g.spanX() - box.x0,
                n.baseY + n.y * size - box.y1,
                n.baseY + std::min((n.y + 1) * size, g.cellsY) - 1 + g.spanY() - box.y0};
    }

    // tileBound() for offsets o and the largest reach c_a (m - h_a) among the apexes.
    float bound(const Offsets& o, float reach) const {
        if (!(reach > 0.0f))
            return kFar;
        const float gx = gap(static_cast<float>(o.x0), static_cast<float>(o.x1));
        const float gy = gap(static_cast<float>(o.y0), static_cast<float>(o.y1));
        if (g.repeat() && (gx >= g.field->width || gy >= g.field->height))
            return kFar;
        const float u = gx * g.invW, v = gy * g.invH;
        return (u * u + v * v) / (reach * reach * kMargin);
    }

    static constexpr float kFar = 3.0e38f;

    // Narrows the cone c of apex b with one cell, remembering the cell in w if it does.
    void narrow(const Apex& b, float& c, Witness* w, int ox, int oy) const {
        const float before = c;
        c = relaxedCell(g, b, ox, oy, c);
        if (c < before)
            *w = {true, b.x + ox, b.y + oy};
    }

    static constexpr float kMargin = 1.0f + 1e-5f;

    // A cell of the map at offset (ox, oy) from apex b, seen within `sectors`: the cheap tests
    // first (not one of the 3x3 already done, can fall in these directions, plain bound below c,
    // falls away from the apex), then relaxedCell() on the corners already read.
    void visitCell(const Cell& cell, int ox, int oy, Sectors sectors, const Apex& b, float& c,
                   Witness* w) const {
        if ((ox >= -1 && ox <= 1 && oy >= -1 && oy <= 1) || beyondPeriod(g, ox, oy))
            return;
        const Sectors falls = cell.falls & sectors;
        if (!falls)
            return;
        const Corners& k = cell.k;
        if (!mayNarrow(k, ox, oy, b, c) || !cornersFallAway(k, ox, oy, g.shape()) ||
            !(falls & sectorsOf(ox, ox + g.spanX(), oy, oy + g.spanY(), g)))
            return;
        const float before = c;
        c = relaxedCell(g, b, ox, oy, c, g.shape(), k);
        if (c < before)
            *w = {true, b.x + ox, b.y + oy};
    }

    // The corners of cell (x, y) of the map (the right and lower ones wrapped or clamped).
    Corners corners(int x, int y) const {
        const HeightField& f = *g.field;
        const int x1 = g.repeat() ? (x + 1 == f.width ? 0 : x + 1) : std::min(x + 1, f.width - 1);
        const int y1 = g.repeat() ? (y + 1 == f.height ? 0 : y + 1) : std::min(y + 1, f.height - 1);
        return {f.at(x, y), f.at(x1, y), f.at(x, y1), f.at(x1, y1)};
    }

    // Whether a cell at offset (ox, oy) with corners k can narrow c by its plain bound: the cheap
    // test before relaxedCell().
    bool mayNarrow(const Corners& k, int ox, int oy, const Apex& b, float c) const {
        const float m = k.max();
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
    // Work units: a cell row of the pyramid's set-up is 1, a tile row (4 texel rows) kTileRowWork,
    // so the set-up is about 2 % of the bar, as it is of an 8192² bake's time, and the bar moves
    // within it.
    const CellGrid grid(field, wrap);
    const int tileRows = (field.height + kTile - 1) / kTile;
    BakeProgress progress(control,
                          std::int64_t(grid.cellsY) + std::int64_t(tileRows) * kTileRowWork);
    const SectorPyramid pyramid(grid, field.maxHeight(), &progress);
    if (progress.stopRequested())
        return cancelledError();
    const EdgeStrips strips(grid);
    const RelaxedCone cone(grid, pyramid, strips, field.maxHeight());
    ConeMap cones(ConeKind::Relaxed, field.width, field.height);
    // Chunks of tile rows fixed by the map alone (simple_partitioner splits ranges in halves down
    // to the grain, however the threads run): each chunk starts without witnesses from above,
    // and a witness changes the order cells are met in, which the per-cell bound's tolerance
    // can see. With TBB's default partitioner the chunks, and a few texels (1 to 4 of 4 million
    // on noise 2048²), changed from run to run.
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tileRows, kChunkRows),
        [&](const tbb::blocked_range<int>& rows) {
            // Witnesses for the row above the tile row and its own rows.
            const int stride = field.width;
            std::vector<Witness> witness(static_cast<std::size_t>(kTile + 1) * stride);
            for (int r = rows.begin(); r < rows.end(); ++r) {
                // Polled per tile and reported per tile row, not per TBB range (many rows): on
                // an 8192² map a cancel took 15-23 s and the first report 9-11 s before.
                const int ty = r * kTile, th = std::min(kTile, field.height - ty);
                for (int tx = 0; tx < field.width; tx += kTile) {
                    if (progress.stopRequested())
                        return;
                    cone.tile(tx, ty, std::min(kTile, field.width - tx), th, witness.data(), stride,
                              cones);
                }
                std::copy_n(witness.begin() + static_cast<std::ptrdiff_t>(th) * stride, stride,
                            witness.begin());
                progress.advance(kTileRowWork);
            }
        },
        tbb::simple_partitioner());
    if (progress.stopRequested())
        return cancelledError();
    progress.finish();
    return cones;
}

} // namespace px

#pragma once
// The cells of the bilinear surface as the cone bakers see them (docs/conventions.md §4,
// docs/cone-maps.md). Coordinates are texel units relative to the apex texel b; a cell is the
// bilinear patch between four neighbouring texel centres, named by its top-left texel.
//   repeat: W x H cells, cell i spans [i, i + 1] (its right corners wrap to texel (i + 1) mod W);
//           the surface is periodic and cells are also met at offsets of whole periods.
//   clamp:  max(W - 1, 1) x max(H - 1, 1) cells inside the box of texel centres; a 1-texel side
//           gives 0-wide cells. Outside that box the surface repeats its nearest edge point, which
//           is nearer to every apex at the same height, so it never limits a cone.
// Every baker computes distances with texelDistance() and heights the same way, so that bounds
// computed from larger regions compare with per-cell bounds exactly in float (c_quick <= c_brute).

#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <algorithm>
#include <cmath>

namespace px::cone {

// A cell's extent in texels along x and y: 1, or 0 for a cell squeezed to a segment (a clamped
// 1-texel side, or an edge strip of a clamped map, see relaxedStripSegment()).
struct Shape {
    int wx = 1, wy = 1;
};

struct CellGrid {
    const HeightField* field = nullptr;
    WrapMode wrap = WrapMode::Repeat;
    int cellsX = 0, cellsY = 0; // cells per period (repeat) or in the map (clamp)
    float invW = 0.0f, invH = 0.0f;

    CellGrid(const HeightField& f, WrapMode mode)
        : field(&f), wrap(mode),
          cellsX(mode == WrapMode::Repeat ? f.width : std::max(f.width - 1, 1)),
          cellsY(mode == WrapMode::Repeat ? f.height : std::max(f.height - 1, 1)),
          invW(1.0f / static_cast<float>(f.width)), invH(1.0f / static_cast<float>(f.height)) {}

    bool repeat() const { return wrap == WrapMode::Repeat; }
    // Width of a cell along x in texels: 1, or 0 for a clamped 1-texel side.
    int spanX() const { return repeat() || field->width > 1 ? 1 : 0; }
    int spanY() const { return repeat() || field->height > 1 ? 1 : 0; }
    Shape shape() const { return {spanX(), spanY()}; }
    // Texel (x, y), wrapped or clamped; bakers only ask within a few periods of the map.
    float texel(int x, int y) const {
        return field->at(resolve(x, field->width), resolve(y, field->height));
    }
    int resolve(int i, int n) const {
        if (!repeat())
            return i < 0 ? 0 : (i >= n ? n - 1 : i);
        while (i < 0)
            i += n;
        while (i >= n)
            i -= n;
        return i;
    }
};

// The four corners of the cell with top-left texel (x, y) (any integers with repeat).
struct Corners {
    float h00, h10, h01, h11;
    float max() const { return std::max(std::max(h00, h10), std::max(h01, h11)); }
};

inline Corners cellCorners(const CellGrid& g, int x, int y) {
    const int x1 = x + g.spanX(), y1 = y + g.spanY();
    return {g.texel(x, y), g.texel(x1, y), g.texel(x, y1), g.texel(x1, y1)};
}

// Horizontal uv distance of a texel-unit offset (dx, dy >= 0). Monotone in dx and dy, in float.
inline float texelDistance(float dx, float dy, const CellGrid& g) {
    const float u = dx * g.invW, v = dy * g.invH;
    return std::sqrt(u * u + v * v);
}

// Distance from b (the origin) along one axis to the interval [lo, hi] (texel units).
inline float gap(float lo, float hi) {
    return std::max(0.0f, std::max(lo, -hi));
}

// The largest double-to-float conversion that does not exceed x: bounds never round wider.
inline float floatDown(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x)
        f = std::nextafter(f, -1.0f);
    return f;
}

// Every finished ratio keeps a relative margin of 2^-20 below its bound, which covers the few
// float roundings in distances and height differences, and is clamped to [0, 1].
inline float finishRatio(float c) {
    if (!(c < 1.0f))
        return 1.0f;
    return std::max(0.0f, c * (1.0f - 1.0f / 1048576.0f));
}

// The apex: texel b and its height.
struct Apex {
    int x, y;
    float h;
};

// Cells with b as a corner (ox, oy: the cell's top-left offset from b). The bilinear surface
// there starts at h_b, so the plain bound dist / (max - h_b) would be 0.
inline bool isApexCell(int ox, int oy, Shape s) {
    return (ox == 0 || ox + s.wx == 0) && (oy == 0 || oy + s.wy == 0);
}
inline bool isApexCell(int ox, int oy, const CellGrid& g) {
    return isApexCell(ox, oy, g.shape());
}

// Exact conservative bound over an apex cell: along each ray from b the secant slope
// (h(q) - h_b) / |q - b| of a bilinear patch is linear in |q - b|, so its maximum S over the
// cell is either the steepest directional derivative at b or on one of the two far edges.
// Returns 1 / S (in uv per unit height), or +inf if the cell never rises above h_b.
double apexConservativeBound(const CellGrid& g, const Apex& b, int ox, int oy, Shape shape);

// Relaxed bound over an apex cell: along a ray from b with h = h_b + A r + K r^2, the surface
// falls away from b only where A + 2 K r < 0, and there the secant is below A / 2. So no falling
// point with h > h_b is steeper than half the steepest directional derivative at b: 2 / A_max.
// +inf if the cell cannot fall anywhere.
double apexRelaxedBound(const CellGrid& g, const Apex& b, int ox, int oy, Shape shape);

// Whether any point of the cell at offset (ox, oy) falls away from b (the radial derivative
// grad h . (q - b) < 0). That derivative is bilinear in the cell, so its corners decide.
bool cellFallsAway(const CellGrid& g, const Apex& b, int ox, int oy, Shape shape);

// The same from the cell's corners, in the same double arithmetic (the one definition both use).
inline bool cornersFallAway(const Corners& k, int ox, int oy, Shape shape) {
    const double sTop = double(k.h10) - k.h00, sBottom = double(k.h11) - k.h01;
    const double tLeft = double(k.h01) - k.h00, tRight = double(k.h11) - k.h10;
    const double r00 = sTop * ox + tLeft * oy, r10 = sTop * (ox + shape.wx) + tRight * oy;
    const double r01 = sBottom * ox + tLeft * (oy + shape.wy);
    const double r11 = sBottom * (ox + shape.wx) + tRight * (oy + shape.wy);
    return std::min(std::min(r00, r10), std::min(r01, r11)) < 0;
}

// Tight lower bound of min |q - b| / (h(q) - h_b) over the cell's points q with h(q) > h_b (and,
// if `fallingOnly`, falling away from b), by branch and bound on sub-rectangles (the bilinear
// maximum of a sub-rectangle is at its corners): within a relative `tolerance` below the true
// minimum when that is below `cutoff`; otherwise some value >= cutoff (pieces that cannot go
// below it are dropped). +inf if no such point exists.
double cellBound(const CellGrid& g, const Apex& b, int ox, int oy, Shape shape, bool fallingOnly,
                 float cutoff, double tolerance);

// The brute-force oracle's tolerance (as tight as the definition allows, for tests), and the
// relaxed bakers' (a 3% narrower cone at worst, for a bake several times faster).
constexpr double kOracleTolerance = 1e-3;
constexpr double kRelaxedTolerance = 3e-2;

} // namespace px::cone

namespace px::cone {

// One cell's contribution to a conservative cone as the brute-force oracle sees it: returns
// min(c, the cell's bound). Plain bound dist / (max - h_b) first; the tight branch and bound
// only where that could lower c.
inline float conservativeCell(const CellGrid& g, const Apex& b, int ox, int oy, float c) {
    if (isApexCell(ox, oy, g))
        return std::min(c, floatDown(apexConservativeBound(g, b, ox, oy, g.shape())));
    const float m = cellCorners(g, b.x + ox, b.y + oy).max();
    if (!(m > b.h))
        return c;
    const float plain =
        texelDistance(gap(ox, ox + g.spanX()), gap(oy, oy + g.spanY()), g) / (m - b.h);
    if (plain >= c)
        return c;
    return std::min(c, std::max(plain, floatDown(cellBound(g, b, ox, oy, g.shape(), false, c,
                                                           kOracleTolerance))));
}

// The same for a relaxed cone: only points where the surface falls away from b limit it. This
// form is for a cell that is not an apex cell, its corners `k` already read (the fast baker's
// inner loop); the cheap rejections come first, the branch and bound only where c may drop.
inline float relaxedCell(const CellGrid& g, const Apex& b, int ox, int oy, float c, Shape shape,
                         const Corners& k) {
    const float m = k.max();
    if (!(m > b.h))
        return c;
    const float plain =
        texelDistance(gap(ox, ox + shape.wx), gap(oy, oy + shape.wy), g) / (m - b.h);
    if (plain >= c || !cornersFallAway(k, ox, oy, shape))
        return c;
    return std::min(
        c, std::max(plain, floatDown(cellBound(g, b, ox, oy, shape, true, c, kRelaxedTolerance))));
}
inline float relaxedCell(const CellGrid& g, const Apex& b, int ox, int oy, float c, Shape shape) {
    if (isApexCell(ox, oy, shape))
        return std::min(c, floatDown(apexRelaxedBound(g, b, ox, oy, shape)));
    const int x = b.x + ox, y = b.y + oy;
    const Corners k{g.texel(x, y), g.texel(x + shape.wx, y), g.texel(x, y + shape.wy),
                    g.texel(x + shape.wx, y + shape.wy)};
    return relaxedCell(g, b, ox, oy, c, shape, k);
}
inline float relaxedCell(const CellGrid& g, const Apex& b, int ox, int oy, float c) {
    return relaxedCell(g, b, ox, oy, c, g.shape());
}

// Clamp only: outside the box of texel centres the surface repeats its edge, constant outward
// but not along the edge, so a ray can leave the solid there (though never conservative cones'
// business: every such point has a nearer twin at the same height). Each strip beyond an edge
// segment is bounded by the segment itself, seen as a 0-wide cell: its points are nearer, and
// along the segment the strip falls exactly where the segment does.
// Side 0..3: left (x = 0), right (x = W - 1), top (y = 0), bottom (y = H - 1); segment i spans
// texels i .. i + 1 along the side.
inline int stripSegments(const CellGrid& g, int side) {
    const int along = side < 2 ? g.field->height : g.field->width;
    const int across = side < 2 ? g.field->width : g.field->height;
    return g.repeat() || across < 2 ? 0 : along - 1; // a 1-texel side: the cells are the strips
}
inline void stripSegment(const CellGrid& g, int side, int i, int& x, int& y, Shape& shape) {
    x = side == 0 ? 0 : (side == 1 ? g.field->width - 1 : i);
    y = side == 2 ? 0 : (side == 3 ? g.field->height - 1 : i);
    shape = side < 2 ? Shape{0, 1} : Shape{1, 0};
}

// With repeat, cells a whole period or more away along an axis are at least 1 uv away and
// cannot narrow a cone (c <= 1, heights <= 1): every baker skips them, so all agree.
inline bool beyondPeriod(const CellGrid& g, int ox, int oy) {
    return g.repeat() && (gap(ox, ox + 1) >= g.field->width || gap(oy, oy + 1) >= g.field->height);
}

} // namespace px::cone

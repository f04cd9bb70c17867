#pragma once
// The relaxed baker's pruning structure. A ray from the apex's column can leave the solid only
// where the surface falls along the ray's direction, away from the apex; which cells can do that
// depends on the direction they are seen in. Directions (in uv) are split into 16 sectors, the 45
// degree octants halved at slopes 1/2 and 2 (26.6 and 63.4 degrees: rational, so every test is
// exact); per cell, a bit per sector says whether the surface can fall along some direction of
// that sector somewhere in the cell (its gradient box against the sector's two edge directions).
// Levels 1+ keep, per node and sector, the highest such cell, rounded up to 16 bits of the map's
// maximum: about 2 bytes per texel for the flags and 10.7 for the maxima. 45 degree sectors let
// through 24 times as many cells that do not fall away from the apex as ones that do (bricks).

#include "bake/BakeProgress.h"
#include "bake/ConeCells.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace px::cone {

constexpr int kSectors = 16;
using Sectors = std::uint16_t; // a bit per sector
constexpr Sectors kAllSectors = 0xffff;

class SectorPyramid {
public:
    // With `progress`, reports a unit of work per cell row of level 0 and stops early,
    // incomplete, once the bake is cancelled: the caller checks before using it.
    SectorPyramid(const CellGrid& grid, float heightMax, BakeProgress* progress = nullptr);

    int levels() const { return static_cast<int>(m_width.size()); }
    int width(int level) const { return m_width[level]; }
    int height(int level) const { return m_height[level]; }
    // Level 0: the sectors along which cell (x, y) can fall.
    Sectors falls(int x, int y) const {
        return m_flags[static_cast<std::size_t>(y) * m_width[0] + x];
    }
    // Levels >= 1: an upper bound of the cells under node (x, y) that can fall along one of
    // `sectors` (-1 if none).
    float maxFalling(int level, int x, int y, Sectors sectors) const {
        const std::uint16_t* q =
            &m_levels[level][(static_cast<std::size_t>(y) * m_width[level] + x) * kSectors];
        unsigned best = 0;
        for (unsigned m = sectors; m != 0; m &= m - 1)
            best = std::max<unsigned>(best, q[__builtin_ctz(m)]);
        return decode(best);
    }
    // The same over all sectors: a cheaper first test, before the sectors are worked out.
    float maxFalling(int level, int x, int y) const {
        return decode(m_any[level][static_cast<std::size_t>(y) * m_width[level] + x]);
    }

    // Starts loading the maxima of nodes (x, y) .. (x + 1, y + 1) of a level, which a search
    // reads next.
    void prefetch(int level, int x, int y) const {
        const std::size_t row = m_width[level], at = static_cast<std::size_t>(y) * row + x;
        __builtin_prefetch(&m_any[level][at]);
        __builtin_prefetch(&m_levels[level][at * kSectors]);
        if (y + 1 < m_height[level]) {
            __builtin_prefetch(&m_any[level][at + row]);
            __builtin_prefetch(&m_levels[level][(at + row) * kSectors]);
        }
    }

private:
    // A stored 0 is a cell of height 0 or none: neither rises above any apex.
    float decode(unsigned stored) const {
        return stored == 0 ? -1.0f : static_cast<float>(stored) * m_scale;
    }

    std::vector<Sectors> m_flags;
    std::vector<std::vector<std::uint16_t>> m_levels; // kSectors per node; m_levels[0] unused
    std::vector<std::vector<std::uint16_t>> m_any;    // their maximum; m_any[0] unused
    std::vector<int> m_width, m_height;
    float m_scale = 0.0f; // height per 16-bit step
};

// A direction (x / W, y / H) scaled by W H to integers; on a square map x and y as they are.
struct Direction {
    long long u, v;
};
inline Direction direction(int x, int y, const CellGrid& g) {
    if (g.field->width == g.field->height)
        return {x, y};
    return {static_cast<long long>(x) * g.field->height,
            static_cast<long long>(y) * g.field->width};
}
// > 0 if b is counterclockwise of a (less than 180 degrees), 0 if parallel.
inline long long cross(const Direction& a, const Direction& b) {
    return a.u * b.v - a.v * b.u;
}

// Sector of a direction, not 0: the octant k (angles [45 k, 45 (k + 1)] from +u towards +v),
// then its half past the octant's middle direction. A direction on a sector's edge may go to
// either neighbour (sectors are closed). Exact in integers.
inline int sectorOf(const Direction& d) {
    static constexpr std::uint8_t kOctant[8] = {0, 1, 3, 2, 7, 6, 4, 5};
    static constexpr int kMiddle[8][2] = {{2, 1},   {1, 2},   {-1, 2}, {-2, 1},
                                          {-2, -1}, {-1, -2}, {1, -2}, {2, -1}};
    const int steep = (d.u < 0 ? -d.u : d.u) < (d.v < 0 ? -d.v : d.v);
    const int octant = kOctant[(d.v < 0) << 2 | (d.u < 0) << 1 | steep];
    const Direction middle{kMiddle[octant][0], kMiddle[octant][1]};
    return 2 * octant + (cross(middle, d) > 0);
}

// The sectors spanned by the directions from the apex to the points of the rectangle
// [x0, x1] x [y0, y1] (texel units relative to the apex): all of them if it holds the apex.
// Otherwise the rectangle lies in an open half-plane, so its directions run from its most
// clockwise corner to its most counterclockwise one. Inline: the relaxed baker asks for every
// node and cell it looks at.
inline Sectors sectorsOf(int x0, int x1, int y0, int y1, const CellGrid& g) {
    if (x0 <= 0 && x1 >= 0 && y0 <= 0 && y1 >= 0)
        return kAllSectors;
    const Direction corners[4] = {direction(x0, y0, g), direction(x1, y0, g), direction(x0, y1, g),
                                  direction(x1, y1, g)};
    Direction first = corners[0], last = corners[0];
    for (int k = 1; k < 4; ++k) {
        if (cross(first, corners[k]) < 0)
            first = corners[k];
        if (cross(last, corners[k]) > 0)
            last = corners[k];
    }
    const int from = sectorOf(first), span = (sectorOf(last) - from) & (kSectors - 1);
    const unsigned arc = (2u << span) - 1u;
    return static_cast<Sectors>(arc << from | arc >> (kSectors - from));
}

// The octants (pairs of sectors 2k, 2k + 1) that hold some of `sectors`, as sectors.
inline Sectors octants(Sectors sectors) {
    const unsigned even = sectors & 0x5555u, odd = sectors & 0xaaaau;
    return static_cast<Sectors>(sectors | even << 1 | odd >> 1);
}

} // namespace px::cone

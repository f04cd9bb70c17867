#pragma once
// The relaxed baker's pruning structure. A ray from the apex's column can leave the solid only
// where the surface falls along the ray's direction, away from the apex; which cells can do that
// depends on the direction they are seen in. Directions (in uv) are split into 8 sectors of 45
// degrees; per cell, a bit per sector says whether the surface can fall along some direction of
// that sector somewhere in the cell (its gradient box against the sector's two edge directions).
// Levels 1+ keep, per node and sector, the highest such cell, rounded up to 16 bits of the map's
// maximum: about 1.6 bytes per texel for the flags and 5.3 for the maxima.

#include "bake/BakeProgress.h"
#include "bake/ConeCells.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace px::cone {

class SectorPyramid {
public:
    // With `progress`, reports a unit of work per cell row of level 0 and stops early,
    // incomplete, once the bake is cancelled: the caller checks before using it.
    SectorPyramid(const CellGrid& grid, float heightMax, BakeProgress* progress = nullptr);

    int levels() const { return static_cast<int>(m_width.size()); }
    int width(int level) const { return m_width[level]; }
    int height(int level) const { return m_height[level]; }
    // Level 0: the sectors along which cell (x, y) can fall.
    std::uint8_t falls(int x, int y) const {
        return m_flags[static_cast<std::size_t>(y) * m_width[0] + x];
    }
    // Levels >= 1: an upper bound of the cells under node (x, y) that can fall along one of
    // `sectors` (-1 if none).
    float maxFalling(int level, int x, int y, std::uint8_t sectors) const {
        const std::uint16_t* q =
            &m_levels[level][(static_cast<std::size_t>(y) * m_width[level] + x) * 8];
        unsigned best = 0;
        for (unsigned m = sectors; m != 0; m &= m - 1)
            best = std::max<unsigned>(best, q[__builtin_ctz(m)]);
        // A stored 0 is a cell of height 0 or none: neither rises above any apex.
        return best == 0 ? -1.0f : static_cast<float>(best) * m_scale;
    }

private:
    std::vector<std::uint8_t> m_flags;
    std::vector<std::vector<std::uint16_t>> m_levels; // 8 per node; m_levels[0] unused
    std::vector<int> m_width, m_height;
    float m_scale = 0.0f; // height per 16-bit step
};

// Sector of the direction (x / W, y / H), x, y not both 0: k covers angles [45 k, 45 (k + 1)]
// degrees from +u towards +v. A direction on a sector's edge may go to either neighbour (sectors
// are closed). Compares |u| and |v| exactly in integers.
inline int sectorOf(int x, int y, const CellGrid& g) {
    static constexpr std::uint8_t kSector[8] = {0, 1, 3, 2, 7, 6, 4, 5};
    // x / W and y / H scaled by W H; on a square map x and y compare as they are.
    const bool square = g.field->width == g.field->height;
    const long long u = square ? x : static_cast<long long>(x) * g.field->height;
    const long long v = square ? y : static_cast<long long>(y) * g.field->width;
    const int steep = (u < 0 ? -u : u) < (v < 0 ? -v : v);
    return kSector[(v < 0) << 2 | (u < 0) << 1 | steep];
}

// For a set of sector bits (the sectors of a shape's corners), the contiguous arc they span:
// every shape here subtends less than 180 degrees, so the largest gap is outside it.
struct ArcTable {
    std::array<std::uint8_t, 256> fill{};
    ArcTable();
};
extern const ArcTable kArcs;

// The sectors spanned by the directions from the apex to the points of the rectangle
// [x0, x1] x [y0, y1] (texel units relative to the apex): all of them if it holds the apex.
// Inline: the relaxed baker asks for every node and cell it looks at.
inline std::uint8_t sectorsOf(int x0, int x1, int y0, int y1, const CellGrid& g) {
    if (x0 <= 0 && x1 >= 0 && y0 <= 0 && y1 >= 0)
        return 0xff;
    const std::uint8_t corners =
        std::uint8_t((1u << sectorOf(x0, y0, g)) | (1u << sectorOf(x1, y0, g)) |
                     (1u << sectorOf(x0, y1, g)) | (1u << sectorOf(x1, y1, g)));
    return kArcs.fill[corners];
}

} // namespace px::cone

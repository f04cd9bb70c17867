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
    float maxFalling(int level, int x, int y, std::uint8_t sectors) const;

private:
    std::vector<std::uint8_t> m_flags;
    std::vector<std::vector<std::uint16_t>> m_levels; // 8 per node; m_levels[0] unused
    std::vector<int> m_width, m_height;
    float m_scale = 0.0f; // height per 16-bit step
};

// The sectors spanned by the directions from the apex to the points of the rectangle
// [x0, x1] x [y0, y1] (texel units relative to the apex): all of them if it holds the apex.
std::uint8_t sectorsOf(int x0, int x1, int y0, int y1, const CellGrid& g);

} // namespace px::cone

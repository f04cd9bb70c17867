#pragma once
// A maximum pyramid over the cells of CellGrid (not MaxMipPyramid, whose clamp layout adds the
// border strips): level 0 holds each cell's corner maximum, the levels above as maxPyramid builds
// them.

#include "bake/ConeCells.h"
#include "parallax/bake/MaxLevel.h"

#include <cstddef>
#include <vector>

namespace px::cone {

class CellPyramid {
public:
    explicit CellPyramid(const CellGrid& grid);

    int levels() const { return static_cast<int>(m_levels.size()); }
    int width(int level) const { return m_levels[level].width; }
    int height(int level) const { return m_levels[level].height; }
    float at(int level, int x, int y) const { return m_levels[level].at(x, y); }

private:
    std::vector<MaxLevel> m_levels;
};

// Floor division and the cell range of extended node e at a level with `nodes` nodes over
// `cells` cells per period: node e mod nodes, shifted by whole periods (docs/cone-maps.md §2,
// "repeat").
inline int floorDiv(int a, int b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

struct CellRange {
    int first, last;
};

inline CellRange nodeCells(int e, int level, int nodes, int cells) {
    const int period = floorDiv(e, nodes);
    const int a = e - period * nodes;
    return {period * cells + (a << level), period * cells + std::min((a + 1) << level, cells) - 1};
}

} // namespace px::cone

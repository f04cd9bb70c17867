#include "bake/CellPyramid.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px::cone {

CellPyramid::CellPyramid(const CellGrid& grid) {
    Level base;
    base.width = grid.cellsX;
    base.height = grid.cellsY;
    base.values.resize(static_cast<std::size_t>(base.width) * base.height);
    tbb::parallel_for(tbb::blocked_range<int>(0, base.height, 16),
                      [&](const tbb::blocked_range<int>& rows) {
                          for (int y = rows.begin(); y < rows.end(); ++y) {
                              for (int x = 0; x < base.width; ++x)
                                  base.values[static_cast<std::size_t>(y) * base.width + x] =
                                      cellCorners(grid, x, y).max();
                          }
                      });
    m_levels.push_back(std::move(base));
    while (m_levels.back().width > 1 || m_levels.back().height > 1) {
        const Level& child = m_levels.back();
        Level parent;
        parent.width = (child.width + 1) / 2;
        parent.height = (child.height + 1) / 2;
        parent.values.resize(static_cast<std::size_t>(parent.width) * parent.height);
        for (int y = 0; y < parent.height; ++y) {
            for (int x = 0; x < parent.width; ++x) {
                float m = child.values[static_cast<std::size_t>(2 * y) * child.width + 2 * x];
                const bool right = 2 * x + 1 < child.width, down = 2 * y + 1 < child.height;
                if (right)
                    m = std::max(
                        m, child.values[static_cast<std::size_t>(2 * y) * child.width + 2 * x + 1]);
                if (down)
                    m = std::max(
                        m, child.values[static_cast<std::size_t>(2 * y + 1) * child.width + 2 * x]);
                if (right && down)
                    m = std::max(m, child.values[static_cast<std::size_t>(2 * y + 1) * child.width +
                                                 2 * x + 1]);
                parent.values[static_cast<std::size_t>(y) * parent.width + x] = m;
            }
        }
        m_levels.push_back(std::move(parent));
    }
}

} // namespace px::cone

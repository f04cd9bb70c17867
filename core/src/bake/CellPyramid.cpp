#include "bake/CellPyramid.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px::cone {

CellPyramid::CellPyramid(const CellGrid& grid) {
    MaxLevel base;
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
    m_levels = maxPyramid(std::move(base));
}

} // namespace px::cone

#include "bake/CellPyramid.h"

#include <algorithm>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px::bake {

CellPyramid::CellPyramid(const HeightField& f, WrapMode wrap) {
    // The cells as shaders/bake/common.glsl defines them: W x H with repeat (the last ones wrap),
    // max(W - 1, 1) x max(H - 1, 1) with clamp (0-wide on a 1-texel side).
    const bool repeat = wrap == WrapMode::Repeat;
    MaxLevel base;
    base.width = repeat ? f.width : std::max(f.width - 1, 1);
    base.height = repeat ? f.height : std::max(f.height - 1, 1);
    base.values.resize(static_cast<std::size_t>(base.width) * base.height);
    const int sx = repeat || f.width > 1 ? 1 : 0, sy = repeat || f.height > 1 ? 1 : 0;
    auto texel = [&](int x, int y) {
        return f.at(repeat ? x % f.width : std::min(x, f.width - 1),
                    repeat ? y % f.height : std::min(y, f.height - 1));
    };
    tbb::parallel_for(tbb::blocked_range<int>(0, base.height, 16),
                      [&](const tbb::blocked_range<int>& rows) {
                          for (int y = rows.begin(); y < rows.end(); ++y) {
                              for (int x = 0; x < base.width; ++x)
                                  base.values[static_cast<std::size_t>(y) * base.width + x] =
                                      std::max(std::max(texel(x, y), texel(x + sx, y)),
                                               std::max(texel(x, y + sy), texel(x + sx, y + sy)));
                          }
                      });
    m_levels = maxPyramid(std::move(base));
}

} // namespace px::bake

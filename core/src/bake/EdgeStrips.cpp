#include "bake/EdgeStrips.h"

#include <algorithm>
#include <utility>

namespace px::bake {

EdgeStrips::EdgeStrips(const HeightField& f, WrapMode wrap) {
    if (wrap == WrapMode::Repeat)
        return;
    for (int side = 0; side < 4; ++side) {
        // As pxStripSegments(): a side of one texel across has no strips (its cells are them).
        const int along = side < 2 ? f.height : f.width;
        const int across = side < 2 ? f.width : f.height;
        const int n = across < 2 ? 0 : along - 1;
        if (n <= 0)
            continue;
        std::vector<float> level(n);
        for (int i = 0; i < n; ++i) {
            const int x = side == 0 ? 0 : (side == 1 ? f.width - 1 : i);
            const int y = side == 2 ? 0 : (side == 3 ? f.height - 1 : i);
            level[i] = side < 2 ? std::max(f.at(x, y), f.at(x, y + 1))
                                : std::max(f.at(x, y), f.at(x + 1, y));
        }
        m_levels[side].push_back(std::move(level));
        while (m_levels[side].back().size() > 1) {
            const std::vector<float>& child = m_levels[side].back();
            std::vector<float> parent((child.size() + 1) / 2);
            for (std::size_t i = 0; i < parent.size(); ++i)
                parent[i] = std::max(child[2 * i],
                                     2 * i + 1 < child.size() ? child[2 * i + 1] : child[2 * i]);
            m_levels[side].push_back(std::move(parent));
        }
    }
}

} // namespace px::bake

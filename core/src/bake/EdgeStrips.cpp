#include "bake/EdgeStrips.h"

#include <utility>

namespace px::cone {

EdgeStrips::EdgeStrips(const CellGrid& g) {
    for (int side = 0; side < 4; ++side) {
        const int n = stripSegments(g, side);
        if (n == 0)
            continue;
        std::vector<float> level(n);
        for (int i = 0; i < n; ++i) {
            int x, y;
            Shape shape;
            stripSegment(g, side, i, x, y, shape);
            level[i] = std::max(g.texel(x, y), g.texel(x + shape.wx, y + shape.wy));
        }
        m_levels[side].push_back(level);
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

float EdgeStrips::narrow(const CellGrid& g, const Apex& b, float c) const {
    for (int side = 0; side < 4; ++side) {
        const auto& levels = m_levels[side];
        if (levels.empty())
            continue;
        const int n = static_cast<int>(levels[0].size());
        std::array<std::pair<int, int>, 64> stack; // (level, index)
        int top = 0;
        stack[top++] = {static_cast<int>(levels.size()) - 1, 0};
        while (top > 0) {
            const auto [level, index] = stack[--top];
            if (!(levels[level][index] > b.h))
                continue;
            const int first = index << level, last = std::min((index + 1) << level, n) - 1;
            int x, y;
            Shape shape;
            stripSegment(g, side, first, x, y, shape);
            const int ox = x - b.x, oy = y - b.y;
            const int lastX = ox + (last - first + 1) * shape.wx,
                      lastY = oy + (last - first + 1) * shape.wy;
            const float u = gap(static_cast<float>(ox), static_cast<float>(lastX)) * g.invW;
            const float v = gap(static_cast<float>(oy), static_cast<float>(lastY)) * g.invH;
            const float rise = levels[level][index] - b.h;
            if (u * u + v * v >= c * c * rise * rise * (1.0f + 1e-5f))
                continue;
            if (level == 0) {
                c = relaxedCell(g, b, ox, oy, c, shape);
                continue;
            }
            for (int k = 1; k >= 0; --k) {
                if (2 * index + k < static_cast<int>(levels[level - 1].size()))
                    stack[top++] = {level - 1, 2 * index + k};
            }
        }
    }
    return c;
}

} // namespace px::cone

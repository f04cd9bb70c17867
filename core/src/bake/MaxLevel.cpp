#include "parallax/bake/MaxLevel.h"

#include <algorithm>

namespace px {

std::vector<MaxLevel> maxPyramid(MaxLevel base) {
    std::vector<MaxLevel> levels;
    levels.push_back(std::move(base));
    while (levels.back().width > 1 || levels.back().height > 1) {
        const MaxLevel& child = levels.back();
        MaxLevel parent;
        parent.width = (child.width + 1) / 2;
        parent.height = (child.height + 1) / 2;
        parent.values.resize(static_cast<std::size_t>(parent.width) * parent.height);
        for (int y = 0; y < parent.height; ++y) {
            for (int x = 0; x < parent.width; ++x) {
                // The first child always exists; the others only inside the child level.
                float m = child.at(2 * x, 2 * y);
                const bool right = 2 * x + 1 < child.width, down = 2 * y + 1 < child.height;
                if (right)
                    m = std::max(m, child.at(2 * x + 1, 2 * y));
                if (down)
                    m = std::max(m, child.at(2 * x, 2 * y + 1));
                if (right && down)
                    m = std::max(m, child.at(2 * x + 1, 2 * y + 1));
                parent.values[static_cast<std::size_t>(y) * parent.width + x] = m;
            }
        }
        levels.push_back(std::move(parent));
    }
    return levels;
}

} // namespace px

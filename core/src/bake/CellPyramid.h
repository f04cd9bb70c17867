#pragma once
// A maximum pyramid over the cells of the bilinear surface (not MaxMipPyramid, whose clamp layout
// adds the border strips), as shaders/bake/quick.glsl reads it: level 0 holds each cell's corner
// maximum, the levels above as maxPyramid builds them.

#include "parallax/bake/MaxLevel.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <glm/glm.hpp>
#include <vector>

namespace px::bake {

class CellPyramid {
public:
    CellPyramid(const HeightField& field, WrapMode wrap);

    int levels() const { return static_cast<int>(m_levels.size()); }
    glm::ivec2 size(int level) const { return {m_levels[level].width, m_levels[level].height}; }
    float at(int level, int x, int y) const { return m_levels[level].at(x, y); }
    const std::vector<MaxLevel>& levelData() const { return m_levels; }

private:
    std::vector<MaxLevel> m_levels;
};

} // namespace px::bake

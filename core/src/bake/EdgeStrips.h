#pragma once
// Clamp only: the 1-D maximum pyramids of the map's edge segments, per side, that
// shaders/bake/strips.glsl walks (the strips beyond the edges limit relaxed cones too). Empty with
// repeat.

#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <array>
#include <vector>

namespace px::bake {

class EdgeStrips {
public:
    EdgeStrips(const HeightField& field, WrapMode wrap);

    int levels(int side) const { return static_cast<int>(m_levels[side].size()); }
    int count(int side, int level) const { return static_cast<int>(m_levels[side][level].size()); }
    float max(int side, int level, int i) const { return m_levels[side][level][i]; }

private:
    std::array<std::vector<std::vector<float>>, 4> m_levels; // per side, level, segment
};

} // namespace px::bake

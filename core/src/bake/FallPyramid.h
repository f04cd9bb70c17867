#pragma once
// The relaxed baker's pruning structure (shaders/bake/relaxed.glsl): a maximum pyramid over the
// cells that can fall at all (the non-flat ones). Per node of levels 1 and up: the highest corner
// of those cells, rounded up to 16 bits of the map's maximum, and the box of their corner
// differences (d h / d x and d h / d y in texel steps), scaled by a power of two of the node's own
// and rounded outwards to 16-bit integers, which tells exactly in integers whether some of them
// may fall away from an apex (a scale per node keeps the signs of the gentle slopes of a map that
// also has steep ones). 12 bytes a node: 4 bytes per cell at level 1, 5.3 in all. Level 0 (the
// cells) is read from the heights.

#include "bake/BakeProgress.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <utility>
#include <vector>

namespace px::bake {

class FallPyramid {
public:
    // With `progress`, reports a unit of work per cell row of level 0 and stops early,
    // incomplete, once the bake is cancelled: the caller checks before using it.
    FallPyramid(const HeightField& field, WrapMode wrap, BakeProgress* progress = nullptr);

    // The top level: 0 for a one-cell map (nothing stored).
    int top() const { return static_cast<int>(m_size.size()) - 1; }
    glm::ivec2 size(int level) const { return m_size[static_cast<std::size_t>(level)]; }
    // Level >= 1: (highest corner in units of unit() | the box's scale exponent + 128 << 16,
    // gx0 | gx1 << 16, gy0 | gy1 << 16).
    glm::uvec3 node(int level, glm::ivec2 n) const {
        const std::uint32_t* p =
            &m_nodes[m_offset[static_cast<std::size_t>(level)] +
                     3 * (static_cast<std::size_t>(n.y) * static_cast<std::size_t>(size(level).x) +
                          static_cast<std::size_t>(n.x))];
        return {p[0], p[1], p[2]};
    }
    // Every level's nodes, level 1 first, 3 words each, as the GPU takes them; the offset of a
    // level in words.
    const std::vector<std::uint32_t>& words() const { return m_nodes; }
    std::size_t offset(int level) const { return m_offset[static_cast<std::size_t>(level)]; }
    // The words, moved out (the pyramid is then empty): for the GPU's upload.
    std::vector<std::uint32_t> takeWords() { return std::move(m_nodes); }
    // The height of a stored highest corner's unit (about the map's maximum / 65535): the
    // kernel decodes q as float(q) * unit(), at least the corner.
    float unit() const { return m_unit; }

private:
    std::vector<glm::ivec2> m_size;
    std::vector<std::size_t> m_offset;
    std::vector<std::uint32_t> m_nodes;
    float m_unit = 0.0f;
};

} // namespace px::bake

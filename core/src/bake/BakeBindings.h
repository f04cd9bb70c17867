#pragma once
// What every C++ compilation of the bake kernels (shaders/bake/) binds: the uniforms and the reads
// the GPU's buffers stand for. BakeKernel derives from it.

#include "bake/CellPyramid.h"
#include "bake/EdgeStrips.h"
#include "bake/FallPyramid.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <glm/glm.hpp>

namespace px::bake {

// NOLINTBEGIN: the names are the kernels' GLSL names.
struct BakeBindings {
    glm::ivec2 pxBakeSize{1, 1};
    bool pxBakeRepeat = true;
    glm::vec2 pxBakeInv{1.0f, 1.0f};
    float pxBakeMax = 0.0f;
    int pxCellLevels = 0;
    int pxFallTop = 0;
    float pxFallUnit = 0.0f;

    const HeightField* field = nullptr;
    const FallPyramid* fall = nullptr;
    const EdgeStrips* strips = nullptr;
    const CellPyramid* cells = nullptr;

    BakeBindings() = default;
    BakeBindings(const HeightField& f, WrapMode wrap)
        : pxBakeSize(f.width, f.height), pxBakeRepeat(wrap == WrapMode::Repeat),
          pxBakeInv(1.0f / static_cast<float>(f.width), 1.0f / static_cast<float>(f.height)),
          pxBakeMax(f.maxHeight()), field(&f) {}

    float pxBakeTexel(glm::ivec2 t) const { return field->at(t.x, t.y); }

    glm::ivec2 pxCellSize(int level) const { return cells->size(level); }
    float pxCellMax(int level, glm::ivec2 n) const { return cells->at(level, n.x, n.y); }

    glm::ivec2 pxFallSize(int level) const { return fall->size(level); }
    glm::uvec3 pxFallNode(int level, glm::ivec2 n) const { return fall->node(level, n); }

    int pxStripLevels(int side) const { return strips ? strips->levels(side) : 0; }
    int pxStripCount(int side, int level) const { return strips->count(side, level); }
    float pxStripMax(int side, int level, int i) const { return strips->max(side, level, i); }
};
// NOLINTEND

} // namespace px::bake

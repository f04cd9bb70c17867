#pragma once
// What a GPU cone bake uploads besides the heights (app/render/src/GpuConeBaker.cpp into the
// buffers of shaders/bake/gpu/bindings.glsl): the pruning pyramids the CPU bakers build, flattened,
// with their level sizes and offsets. The GPU runs the same kernels (shaders/bake/) on them.

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace px {

struct ConeBakeInputs {
    // Relaxed: the pyramid of falling cells (level 1 first, 3 words a node).
    std::vector<std::uint32_t> fallWords;
    int fallTop = 0;
    float fallUnit = 0.0f;
    std::vector<glm::ivec2> fallSizes; // per level, 0 first
    std::vector<int> fallOffsets;      // words, per level (level 0: none)
    // Conservative: the cells' maximum pyramid, level 0 first; relaxed with clamp: the edge
    // strips' pyramids, per side and level.
    std::vector<float> levelValues;
    int cellLevels = 0;
    std::vector<glm::ivec2> cellSizes;
    std::vector<int> cellOffsets;
    std::array<int, 4> stripLevels{};
    std::array<int, 128> stripCounts{};  // side * 32 + level
    std::array<int, 128> stripOffsets{}; // side * 32 + level
};

// The inputs of a `kind` bake of `field` (built on every core). Errors: an empty field, a map
// with more than 32 pyramid levels, cancellation (cancelledError()).
Result<ConeBakeInputs> prepareConeBake(const HeightField& field, WrapMode wrap, ConeKind kind,
                                       const BakeControl& control = {});

} // namespace px

#pragma once
// What every C++ compilation of the trace kernels binds: the uniforms of common.glsl and the
// samplers standing in for the GPU's textures. TraceKernel and HardwareModelKernel derive from it
// and differ only in how a filtered read is made.

#include "parallax/bake/ConeMap.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/heightfield/HeightField.h"

#include <glm/glm.hpp>

namespace px::kernel {

// NOLINTBEGIN: the names are the kernels' GLSL names.
struct KernelBindings {
    // Uniforms (see common.glsl).
    glm::ivec2 pxMapSize{1, 1};
    bool pxWrapRepeat = true;
    float pxHeightMax = 1.0f;
    float pxScale = 0.0f;
    int pxMinLayers = 8;
    int pxMaxLayers = 32;
    int pxRefineSteps = 0;
    int pxMaxSteps = 64;
    int pxMaxMipTop = 0;
    int pxFetches = 0;

    // Samplers.
    const HeightField* heightField = nullptr;
    const ConeMap* coneMap = nullptr;
    const MaxMipPyramid* pyramid = nullptr;

    float pxHeightTexel(glm::ivec2 i) const { return heightField->at(i.x, i.y); }
    glm::vec2 pxConeTexel(glm::ivec2 i) const {
        return glm::vec2(heightField->at(i.x, i.y), coneMap->g(i.x, i.y));
    }
    float pxMaxMipNode(int level, glm::ivec2 n) const { return pyramid->at(level, n.x, n.y); }
};
// NOLINTEND

} // namespace px::kernel

#pragma once
// The GLSL trace kernels of shaders/trace/, compiled as C++: GLM stands in for GLSL, and the
// kernel files are included inside this struct so that their globals (uniforms, the fetch counter)
// become members. What the GPU runs and what the CPU runs are therefore the same code.

#include "parallax/bake/ConeMap.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/heightfield/HeightField.h"

#include <glm/glm.hpp>

namespace px::kernel {

using namespace glm; // the kernel files speak GLSL

// NOLINTBEGIN: the included kernel code follows GLSL, not this project's C++ style.
struct TraceKernel {
    // Uniforms (see common.glsl).
    ivec2 pxMapSize{1, 1};
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

    float pxHeightTexel(ivec2 i) const { return heightField->at(i.x, i.y); }
    vec2 pxConeTexel(ivec2 i) const {
        return vec2(heightField->at(i.x, i.y), coneMap->g(i.x, i.y));
    }
    float pxMaxMipNode(int level, ivec2 n) const { return pyramid->at(level, n.x, n.y); }

    // GlslSubsetBegin.h must stay first and GlslSubsetEnd.h last: not sorted.
    // clang-format off
#include "trace/GlslSubsetBegin.h"
#include "trace/common.glsl"
#include "trace/cone_conservative.glsl"
#include "trace/cone_relaxed.glsl"
#include "trace/exact.glsl"
#include "trace/march.glsl"
#include "trace/normals.glsl"
#include "trace/offset.glsl"
#include "trace/pom.glsl"
#include "trace/pyramid.glsl"
#include "trace/relief.glsl"
#include "trace/secant.glsl"
#include "trace/shadow.glsl"
#include "trace/steep.glsl"
#include "trace/walk.glsl"
#include "trace/GlslSubsetEnd.h"
    // clang-format on
};
// NOLINTEND

} // namespace px::kernel

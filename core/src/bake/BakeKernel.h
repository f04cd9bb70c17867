#pragma once
// The GLSL bake kernels of shaders/bake/, compiled as C++ (as TraceKernel.h does the trace
// kernels): GLM stands in for GLSL, and the kernel files are included inside this struct so that
// their globals (the tile, the stacks) become members. One instance per thread. What the GPU
// runs and what the CPU runs are the same code.

#include "bake/BakeBindings.h"

#include <glm/glm.hpp>

namespace px::bake {

using namespace glm; // the kernel files speak GLSL

// NOLINTBEGIN: the included kernel code follows GLSL, not this project's C++ style.
struct BakeKernel : BakeBindings {
    using BakeBindings::BakeBindings;
// clang-format off
#include "glsl/GlslSubsetBegin.h"
#include "bake/kernels.glsl"
#include "glsl/GlslSubsetEnd.h"
    // clang-format on
};
// NOLINTEND

} // namespace px::bake

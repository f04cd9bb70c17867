#pragma once
// The GLSL trace kernels of shaders/trace/, compiled as C++: GLM stands in for GLSL, and the
// kernel files are included inside this struct so that their globals (uniforms, the fetch counter)
// become members. What the GPU runs and what the CPU runs are therefore the same code.

#include "KernelBindings.h"

#include <glm/glm.hpp>

namespace px::kernel {

using namespace glm; // the kernel files speak GLSL

// NOLINTBEGIN: the included kernel code follows GLSL, not this project's C++ style.
struct TraceKernel : KernelBindings {
#include "KernelFiles.inc"
};
// NOLINTEND

} // namespace px::kernel

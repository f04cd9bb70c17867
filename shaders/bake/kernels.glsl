// The bake kernels, in declaration order: the C++ compilation (core/src/bake/BakeKernel.h) and the
// compute shader generator (core/src/shader/BakeShader.cpp) both take this list.
#include "bake/common.glsl"
#include "bake/cells.glsl"
#include "bake/strips.glsl"
#include "bake/relaxed.glsl"
#include "bake/quick.glsl"

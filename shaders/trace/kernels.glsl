// The trace kernels' files in declaration order (GLSL wants each function declared before its
// use): the one list. The C++ kernel structs include this file (core/src/trace/KernelFiles.inc)
// and the shader generator reads it for the trace part of its library (ShaderGenerator.cpp).
#include "trace/common.glsl"
#include "trace/walk.glsl"
#include "trace/exact.glsl"
#include "trace/offset.glsl"
#include "trace/march.glsl"
#include "trace/steep.glsl"
#include "trace/pom.glsl"
#include "trace/relief.glsl"
#include "trace/secant.glsl"
#include "trace/cone_conservative.glsl"
#include "trace/cone_relaxed.glsl"
#include "trace/pyramid.glsl"
#include "trace/shadow.glsl"
#include "trace/normals.glsl"

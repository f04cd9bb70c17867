// Opens the region where GLSL kernels (shaders/trace/, shaders/bake/) are compiled as C++ (no
// include guard: it is included once per region, closed by GlslSubsetEnd.h). The C++ compiler
// checks there what it can of the GLSL subset the kernels are written in (shaders/trace/README.md),
// as errors:
//   double-promotion: GLSL floats never become doubles; a literal without `f` or a float mixed
//                     with a double would compute in double here and in float on the GPU.
//   float-conversion: GLSL converts float to int and double to float only explicitly.
#pragma GCC diagnostic push
#pragma GCC diagnostic error "-Wdouble-promotion"
#pragma GCC diagnostic error "-Wfloat-conversion"

// One kernel-style function compiled inside the GLSL-subset region, the way TraceKernel.h
// compiles shaders/trace/: the ctests core.trace.GlslSubset.* compile it with each SNIPPET and
// expect the clean one to pass and each violation to be an error naming its check.
#include "glsl/GlslSubsetBegin.h"
struct Kernel {
#if SNIPPET == 0 // clean: float literals, explicit conversions
    float half(float x) {
        return x * 0.5f + float(int(x));
    }
#elif SNIPPET == 1 // a literal without `f`: double arithmetic on the CPU, float on the GPU
    float half(float x) {
        return x * 0.5;
    }
#elif SNIPPET == 2 // an implicit float -> int conversion, which GLSL refuses
    int half(float x) {
        return x * 0.5f;
    }
#elif SNIPPET == 3 // an implicit double -> float conversion
    float half(double x) {
        return x;
    }
#endif
};
#include "glsl/GlslSubsetEnd.h"

int main() {
    return static_cast<int>(Kernel().half(2.0f));
}

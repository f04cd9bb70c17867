#pragma once
// The production kernels (PX_HAS_HARDWARE_SAMPLING: what the GPU runs by default) compiled as C++,
// with a model of a GPU texture unit standing in for the hardware: bilinear weights rounded to
// `subTexelBits` fractional bits. Most GPUs filter with 8-bit weights (multiples of 1/256; D3D
// asks for at least that, GL for nothing), llvmpipe with finer ones, so llvmpipe alone cannot show
// what 8 bits cost; this model can, on the CPU, for the same rays. Gathers return texels, exact.

#include "KernelBindings.h"

#include <glm/glm.hpp>

namespace px::kernel {

using namespace glm; // the kernel files speak GLSL

// NOLINTBEGIN: the included kernel code follows GLSL, not this project's C++ style.
struct HardwareModelKernel : KernelBindings {
    int subTexelBits = 8;

    // The texture unit: the weight rounded to the nearest multiple of 2^-bits.
    float pxWeight(float f) const {
        const float steps = float(1 << subTexelBits);
        return floor(f * steps + 0.5f) / steps;
    }
    ivec4 footprintOf(vec2 uv, vec2& f) {
        const vec2 c(uv.x * float(pxMapSize.x) - 0.5f, uv.y * float(pxMapSize.y) - 0.5f);
        const vec2 base = floor(c);
        f = vec2(pxWeight(c.x - base.x), pxWeight(c.y - base.y));
        return pxFootprint(ivec2(base));
    }
    float pxHeightFiltered(vec2 uv) {
        vec2 f;
        const ivec4 q = footprintOf(uv, f);
        const float top = mix(pxHeightTexel(ivec2(q.x, q.z)), pxHeightTexel(ivec2(q.y, q.z)), f.x);
        const float bottom =
            mix(pxHeightTexel(ivec2(q.x, q.w)), pxHeightTexel(ivec2(q.y, q.w)), f.x);
        return mix(top, bottom, f.y);
    }
    vec2 pxConeFiltered(vec2 uv) {
        vec2 f;
        const ivec4 q = footprintOf(uv, f);
        const vec2 top = mix(pxConeTexel(ivec2(q.x, q.z)), pxConeTexel(ivec2(q.y, q.z)), f.x);
        const vec2 bottom = mix(pxConeTexel(ivec2(q.x, q.w)), pxConeTexel(ivec2(q.y, q.w)), f.x);
        return mix(top, bottom, f.y);
    }
    vec4 pxHeightGather(ivec2 cell) {
        const ivec4 q = pxFootprint(cell);
        return vec4(pxHeightTexel(ivec2(q.x, q.z)), pxHeightTexel(ivec2(q.y, q.z)),
                    pxHeightTexel(ivec2(q.x, q.w)), pxHeightTexel(ivec2(q.y, q.w)));
    }
    vec4 pxConeGatherHeights(ivec2 cell) { return pxHeightGather(cell); }
    vec4 pxConeGatherRoots(ivec2 cell) {
        const ivec4 q = pxFootprint(cell);
        return vec4(coneMap->g(q.x, q.z), coneMap->g(q.y, q.z), coneMap->g(q.x, q.w),
                    coneMap->g(q.y, q.w));
    }

#define PX_HAS_HARDWARE_SAMPLING 1
#include "KernelFiles.inc"
#undef PX_HAS_HARDWARE_SAMPLING
};
// NOLINTEND

} // namespace px::kernel

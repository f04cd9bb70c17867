// The GPU's side of the bake kernels' bindings (shaders/bake/common.glsl, quick.glsl,
// relaxed.glsl, strips.glsl): the maps as storage buffers, as app/render/src/GpuConeBaker.cpp
// uploads them, and uniforms. The generator adds `const bool pxBakeRepeat`. The C++ side is
// core/src/bake/BakeBindings.h.

layout(std430, binding = 0) readonly buffer PxBakeHeights {
    float pxBakeHeights[];
};
// The relaxed baker's FallPyramid, level 1 first, 3 words a node.
layout(std430, binding = 1) readonly buffer PxBakeFall {
    uint pxBakeFallWords[];
};
// The quick baker's CellPyramid, level 0 first; or the clamp strips' pyramids, per side and level.
layout(std430, binding = 2) readonly buffer PxBakeLevels {
    float pxBakeLevelValues[];
};
layout(std430, binding = 3) writeonly buffer PxBakeCones {
    float pxBakeCones[];
};

uniform ivec2 pxBakeSize;
uniform vec2 pxBakeInv;
uniform float pxBakeMax;
// The work of this dispatch: tiles (relaxed) or texels (quick) first .. end - 1.
uniform int pxBakeFirst;
uniform int pxBakeEnd;

uniform int pxFallTop;
uniform float pxFallUnit;
uniform ivec2 pxFallSizes[32];
uniform int pxFallOffsets[32];

uniform int pxCellLevels;
uniform ivec2 pxCellSizes[32];
uniform int pxCellOffsets[32];

// Per side (4) and level (up to 32): the strips' node counts and offsets; levels per side.
uniform int pxStripLevelCounts[4];
uniform int pxStripCounts[128];
uniform int pxStripOffsets[128];

float pxBakeTexel(ivec2 t) {
    return pxBakeHeights[t.y * pxBakeSize.x + t.x];
}

ivec2 pxFallSize(int level) {
    return pxFallSizes[level];
}

uvec3 pxFallNode(int level, ivec2 n) {
    int at = pxFallOffsets[level] + 3 * (n.y * pxFallSizes[level].x + n.x);
    return uvec3(pxBakeFallWords[at], pxBakeFallWords[at + 1], pxBakeFallWords[at + 2]);
}

ivec2 pxCellSize(int level) {
    return pxCellSizes[level];
}

float pxCellMax(int level, ivec2 n) {
    return pxBakeLevelValues[pxCellOffsets[level] + n.y * pxCellSizes[level].x + n.x];
}

int pxStripLevels(int side) {
    return pxStripLevelCounts[side];
}

int pxStripCount(int side, int level) {
    return pxStripCounts[side * 32 + level];
}

float pxStripMax(int side, int level, int i) {
    return pxBakeLevelValues[pxStripOffsets[side * 32 + level] + i];
}

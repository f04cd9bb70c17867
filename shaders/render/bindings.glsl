// The GPU side of the trace kernels' bindings (../trace/common.glsl). Uniform declarations are
// written by the generator for exactly the names the kept code reads; pxWrapRepeat is a constant
// of the variant. Heights are read with texelFetch and filtered by the shared code, so the GPU and
// the CPU agree to the bit (R16 and R32F textures: never 8 bits).

int pxFetches = 0;

// The height map's level the kernels read, and its size. Marching techniques read the level that
// the pixel's footprint asks for (taken before any loop); cone, pyramid and exact read level 0,
// the level their pre-computed maps describe.
int pxHeightLevel = 0;
ivec2 pxMapSize = ivec2(1, 1);

void pxUseHeightLevel(int level) {
    pxHeightLevel = level;
    pxMapSize = textureSize(pxHeightMap, level);
}

float pxHeightTexel(ivec2 texel) {
    return texelFetch(pxHeightMap, texel, pxHeightLevel).r;
}

// Cone maps are RG32F: R the height, G sqrt(cone ratio) (docs/conventions.md §4).
vec2 pxConeTexel(ivec2 texel) {
    return texelFetch(pxConeMap, texel, 0).rg;
}

// The max-mip pyramid is one R32F atlas, level L starting at row pxMaxMipRows[L]
// (MaxMipPyramid::atlas(): GL mip chains round sizes down and would lose the odd borders).
float pxMaxMipNode(int level, ivec2 node) {
    return texelFetch(pxMaxMipAtlas, ivec2(node.x, pxMaxMipRows[level] + node.y), 0).r;
}

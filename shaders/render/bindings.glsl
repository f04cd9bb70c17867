// The GPU side of the trace kernels' bindings (../trace/common.glsl). Uniform declarations are
// written by the generator for exactly the names the kept code reads; pxWrapRepeat is a constant
// of the variant. Two flavours (VariantKey::flavour): `verify` reads texels with texelFetch and
// the shared code filters them, so the GPU and the CPU agree to the bit; `production`
// (PX_HAS_HARDWARE_SAMPLING) lets the texture units filter, as an engine would. Heights are R16 or
// R32F textures, never 8 bits; the samplers' wrap mode is the material's.

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

// Cone maps are RG32F, or RG16 where heights and cones are 16-bit: R the height, G sqrt(cone
// ratio) (docs/conventions.md §4).
vec2 pxConeTexel(ivec2 texel) {
    return texelFetch(pxConeMap, texel, 0).rg;
}

// The max-mip pyramid is one R32F atlas, level L starting at row pxMaxMipRows[L]
// (MaxMipPyramid::atlas(): GL mip chains round sizes down and would lose the odd borders).
float pxMaxMipNode(int level, ivec2 node) {
    return texelFetch(pxMaxMipAtlas, ivec2(node.x, pxMaxMipRows[level] + node.y), 0).r;
}

#if defined(PX_HAS_HARDWARE_SAMPLING)
// The production flavour's reads (called by pxHeight, pxConeSample, pxCellCorners and
// pxConeCorners in ../trace/). The uv derivatives the hardware selects the height mip from: zero
// (level 0, bilinear) unless a marching technique in the surface pass sets the pixel's footprint
// (then trilinear, as textureGrad in an engine's parallax loop).
vec2 pxHeightDx = vec2(0.0f, 0.0f);
vec2 pxHeightDy = vec2(0.0f, 0.0f);

void pxUseHeightGradients(vec2 dx, vec2 dy) {
    pxHeightDx = dx;
    pxHeightDy = dy;
}

float pxHeightFiltered(vec2 uv) {
    return textureGrad(pxHeightMap, uv, pxHeightDx, pxHeightDy).r;
}

// Cone maps are filtered bilinearly at level 0: (height, sqrt(cone ratio)).
vec2 pxConeFiltered(vec2 uv) {
    return textureLod(pxConeMap, uv, 0.0f).rg;
}

// textureGather at the centre of the cell's 2x2 footprint returns its texels as
// (x0 y1, x1 y1, x1 y0, x0 y0) (y1 the row below): reordered to (h00, h10, h01, h11).
vec2 pxGatherUv(ivec2 cell) {
    return vec2(float(cell.x + 1) / float(pxMapSize.x), float(cell.y + 1) / float(pxMapSize.y));
}

vec4 pxHeightGather(ivec2 cell) {
    vec4 g = textureGather(pxHeightMap, pxGatherUv(cell), 0);
    return vec4(g.w, g.z, g.x, g.y);
}

vec4 pxConeGatherHeights(ivec2 cell) {
    vec4 g = textureGather(pxConeMap, pxGatherUv(cell), 0);
    return vec4(g.w, g.z, g.x, g.y);
}

vec4 pxConeGatherRoots(ivec2 cell) {
    vec4 g = textureGather(pxConeMap, pxGatherUv(cell), 1);
    return vec4(g.w, g.z, g.x, g.y);
}
#endif

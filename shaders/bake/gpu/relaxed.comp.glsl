// The relaxed cone bake on the GPU: one invocation per 4 x 4 tile of the slice this dispatch
// covers (tiles pxBakeFirst .. pxBakeEnd - 1, row by row), no seeds (the cones are the same with
// or without them), the kernel of shaders/bake/relaxed.glsl.
void main() {
    int tile = pxBakeFirst + int(gl_GlobalInvocationID.x);
    if (tile >= pxBakeEnd)
        return;
    int tilesX = (pxBakeSize.x + PX_TILE_W - 1) / PX_TILE_W;
    ivec2 origin = ivec2(tile % tilesX * PX_TILE_W, tile / tilesX * PX_TILE_H);
    ivec2 size = ivec2(min(PX_TILE_W, pxBakeSize.x - origin.x), min(PX_TILE_H, pxBakeSize.y - origin.y));
    for (int j = 0; j < PX_TILE_H; ++j)
        pxSeedRow[j] = ivec3(0, 0, 0);
    for (int i = 0; i < PX_TILE_W; ++i)
        pxSeedColumn[i] = ivec3(0, 0, 0);
    pxRelaxedTile(origin, size);
    for (int k = 0; k < size.x * size.y; ++k)
        pxBakeCones[(origin.y + k / size.x) * pxBakeSize.x + origin.x + k % size.x] = pxRelaxedResult(k);
}

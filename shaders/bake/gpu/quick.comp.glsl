// The quick conservative cone bake on the GPU: one invocation per texel of the slice this
// dispatch covers (texels pxBakeFirst .. pxBakeEnd - 1, row by row), the kernel of
// shaders/bake/quick.glsl.
void main() {
    int texel = pxBakeFirst + int(gl_GlobalInvocationID.x);
    if (texel >= pxBakeEnd)
        return;
    pxBakeCones[texel] = pxQuickResult(ivec2(texel % pxBakeSize.x, texel / pxBakeSize.x));
}

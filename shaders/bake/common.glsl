// Shared by the cone bakers (docs/cone-maps.md §1, §2): the grid of cells of the bilinear surface
// as the bakers see it. Coordinates are texels; a cell is the patch between four neighbouring texel
// centres, named by its top-left texel.
//   repeat: W x H cells, cell i spans [i, i + 1] (its right corners wrap to texel (i + 1) mod W);
//           cells are also met at offsets of whole periods.
//   clamp:  max(W - 1, 1) x max(H - 1, 1) cells inside the box of texel centres; a 1-texel side
//           gives 0-wide cells.
//
// Bindings each side provides (C++: core/src/bake/BakeBindings.h; GPU: shaders/bake/gpu/):
//   ivec2 pxBakeSize; bool pxBakeRepeat; vec2 pxBakeInv (1 / W, 1 / H as floats); float pxBakeMax
//   float pxBakeTexel(ivec2 texel)        texel inside the map

// Marks values both compilers must evaluate as written (no fused or reassociated operations), as
// the trace kernels do (shaders/trace/common.glsl). The shader generator defines it as `precise`.
#ifndef PX_PRECISE
#define PX_PRECISE
#endif

#define PX_BAKE_FAR 3.0e38f

// floor(a / b) for b > 0, well defined for negative a.
int pxBakeFloorDiv(int a, int b) {
    return a >= 0 ? a / b : -((-a - 1) / b) - 1;
}

int pxBakeResolve(int i, int n) {
    if (!pxBakeRepeat)
        return clamp(i, 0, n - 1);
    if (i >= 0 && i < n)
        return i;
    return i - n * pxBakeFloorDiv(i, n);
}

// Texel (x, y), wrapped or clamped.
float pxBakeHeight(ivec2 t) {
    return pxBakeTexel(ivec2(pxBakeResolve(t.x, pxBakeSize.x), pxBakeResolve(t.y, pxBakeSize.y)));
}

// Cells per period (repeat) or in the map (clamp), and a cell's extent in texels (1, or 0 for a
// clamped 1-texel side).
ivec2 pxBakeCells() {
    if (pxBakeRepeat)
        return pxBakeSize;
    return ivec2(max(pxBakeSize.x - 1, 1), max(pxBakeSize.y - 1, 1));
}
ivec2 pxBakeSpan() {
    return ivec2(pxBakeRepeat || pxBakeSize.x > 1 ? 1 : 0, pxBakeRepeat || pxBakeSize.y > 1 ? 1 : 0);
}

// The corners (h00, h10, h01, h11) of the cell with top-left texel t and extent `span`.
vec4 pxBakeCorners(ivec2 t, ivec2 span) {
    return vec4(pxBakeHeight(t), pxBakeHeight(ivec2(t.x + span.x, t.y)),
                pxBakeHeight(ivec2(t.x, t.y + span.y)),
                pxBakeHeight(ivec2(t.x + span.x, t.y + span.y)));
}

float pxBakeMax4(vec4 k) {
    return max(max(k.x, k.y), max(k.z, k.w));
}

// Distance from the apex (the origin) along one axis to [lo, hi] (texels).
float pxBakeGap(float lo, float hi) {
    return max(0.0f, max(lo, -hi));
}
int pxBakeGapInt(int lo, int hi) {
    return max(0, max(lo, -hi));
}

// Horizontal uv distance of a texel offset (dx, dy >= 0); every baker computes distances so, so
// that bounds of larger regions and of single cells compare exactly in float.
float pxBakeDistance(float dx, float dy) {
    PX_PRECISE float u = dx * pxBakeInv.x;
    PX_PRECISE float v = dy * pxBakeInv.y;
    PX_PRECISE float d = sqrt(u * u + v * v);
    return d;
}

// The same squared, without the root: for tests against a squared bound.
float pxBakeDistance2(float dx, float dy) {
    PX_PRECISE float u = dx * pxBakeInv.x;
    PX_PRECISE float v = dy * pxBakeInv.y;
    PX_PRECISE float d2 = u * u + v * v;
    return d2;
}

// The next float towards minus infinity (f finite or +infinity).
float pxBakeNextDown(float f) {
    if (f > 0.0f)
        return uintBitsToFloat(floatBitsToUint(f) - 1u);
    if (f < 0.0f)
        return uintBitsToFloat(floatBitsToUint(f) + 1u);
    return -uintBitsToFloat(1u);
}

// The largest float that does not exceed x: bounds never round wider.
float pxBakeFloatDown(double x) {
    float f = float(x);
    if (double(f) > x)
        f = pxBakeNextDown(f);
    return f;
}

// Every finished ratio keeps a relative margin of 2^-20 below its bound, which covers the few
// float roundings in distances and height differences, and is clamped to [0, 1].
float pxBakeFinish(float c) {
    if (!(c < 1.0f))
        return 1.0f;
    PX_PRECISE float r = c * (1.0f - 1.0f / 1048576.0f);
    return max(0.0f, r);
}

// With repeat, cells a whole period or more away along an axis are at least 1 uv away and cannot
// narrow a cone (c <= 1, heights <= 1): every baker skips them, so all agree.
bool pxBakeBeyondPeriod(int ox, int oy) {
    return pxBakeRepeat && (pxBakeGapInt(ox, ox + 1) >= pxBakeSize.x ||
                            pxBakeGapInt(oy, oy + 1) >= pxBakeSize.y);
}

// Cells with the apex as a corner (o: the cell's top-left offset from the apex).
bool pxBakeIsApexCell(ivec2 o, ivec2 span) {
    return (o.x == 0 || o.x + span.x == 0) && (o.y == 0 || o.y + span.y == 0);
}

// Shared by every technique. Conventions: docs/conventions.md §2 and §5; cell space
// and the cell solve: docs/cone-maps.md, "Terms" (cell coordinates X = uW - 1/2).
//
// Bindings each side provides:
//   ivec2 pxMapSize; bool pxWrapRepeat; float pxHeightMax; float pxScale;
//   int pxMinLayers, pxMaxLayers, pxRefineSteps, pxMaxSteps; int pxFetches;
//   float pxHeightTexel(ivec2 texel)      texel already wrapped or clamped
//   vec2  pxConeTexel(ivec2 texel)        (height, sqrt(cone ratio))
//   float pxMaxMipNode(int level, ivec2 node)
//   ivec2 pxMaxMipSize(int level); int pxMaxMipTop

#define PX_BIG 1.0e30f

// The most cells one exact walk may visit (kMaxStepsLimit): more than the rays of any view the
// tracers accept cross, so a walk ends at its far end, not at this budget.
#define PX_WALK_LIMIT 16777216

// Marks values whose every operation both compilers must evaluate as written: GLSL compilers may
// otherwise reassociate or fuse them (Mesa does), and the CPU and GPU would part ways in the last
// bits, which iterated refinements amplify. The shader generator defines it as `precise`.
#ifndef PX_PRECISE
#define PX_PRECISE
#endif

// floor(a / b) for b > 0, well defined for negative a (GLSL leaves % and / on negatives open).
int pxFloorDiv(int a, int b) {
    return a >= 0 ? a / b : -((-a - 1) / b) - 1;
}

int pxWrapIndex(int i, int size) {
    if (!pxWrapRepeat)
        return clamp(i, 0, size - 1);
    if (i >= 0 && i < size)
        return i; // inside the tile, the common case: no division
    return i - size * pxFloorDiv(i, size);
}

ivec2 pxWrapTexel(ivec2 texel) {
    return ivec2(pxWrapIndex(texel.x, pxMapSize.x), pxWrapIndex(texel.y, pxMapSize.y));
}

// The index after an already wrapped one: the same as pxWrapIndex(i + 1) for the unwrapped i,
// without another division (GPUs and SIMD CPUs divide integers slowly).
int pxNextIndex(int wrapped, int unwrapped, int size) {
    if (!pxWrapRepeat)
        return clamp(unwrapped + 1, 0, size - 1);
    return wrapped + 1 == size ? 0 : wrapped + 1;
}

// The 2x2 footprint with top-left texel i, wrapped: (x0, x1, y0, y1).
ivec4 pxFootprint(ivec2 i) {
    ivec2 w = pxWrapTexel(i);
    return ivec4(w.x, pxNextIndex(w.x, i.x, pxMapSize.x), w.y, pxNextIndex(w.y, i.y, pxMapSize.y));
}

// Bilinear weights and the top-left texel of the 2x2 footprint of a uv.
vec2 pxCellCoords(vec2 uv) {
    return vec2(uv.x * float(pxMapSize.x) - 0.5f, uv.y * float(pxMapSize.y) - 0.5f);
}

// mix() written out: x (1 - a) + y a, as GLM evaluates it. GLSL compilers lower mix() as they
// see fit (Mesa sometimes to x + a (y - x)), which differs in the last bit.
float pxLerp(float x, float y, float a) {
    PX_PRECISE float r = x * (1.0f - a) + y * a;
    return r;
}

vec2 pxLerp2(vec2 x, vec2 y, float a) {
    PX_PRECISE vec2 r = x * (1.0f - a) + y * a;
    return r;
}

// One bilinear sample of the height map: one fetch.
float pxHeight(vec2 uv) {
    pxFetches += 1;
#if defined(PX_HAS_HARDWARE_SAMPLING)
    return pxHeightFiltered(uv); // the production flavour: the texture unit filters
#else
    vec2 c = pxCellCoords(uv);
    vec2 base = floor(c);
    vec2 f = c - base;
    ivec4 q = pxFootprint(ivec2(base));
    float h00 = pxHeightTexel(ivec2(q.x, q.z));
    float h10 = pxHeightTexel(ivec2(q.y, q.z));
    float h01 = pxHeightTexel(ivec2(q.x, q.w));
    float h11 = pxHeightTexel(ivec2(q.y, q.w));
    return pxLerp(pxLerp(h00, h10, f.x), pxLerp(h01, h11, f.x), f.y);
#endif
}

// One bilinear sample of the cone map: (height, cone ratio). G holds sqrt(ratio)
// (docs/conventions.md §4), interpolated before squaring as a GPU sampler would.
vec2 pxConeSample(vec2 uv) {
    pxFetches += 1;
#if defined(PX_HAS_HARDWARE_SAMPLING)
    vec2 s = pxConeFiltered(uv);
#else
    vec2 c = pxCellCoords(uv);
    vec2 base = floor(c);
    vec2 f = c - base;
    ivec4 q = pxFootprint(ivec2(base));
    vec2 a = pxConeTexel(ivec2(q.x, q.z));
    vec2 b = pxConeTexel(ivec2(q.y, q.z));
    vec2 d = pxConeTexel(ivec2(q.x, q.w));
    vec2 e = pxConeTexel(ivec2(q.y, q.w));
    vec2 s = pxLerp2(pxLerp2(a, b, f.x), pxLerp2(d, e, f.x), f.y);
#endif
    return vec2(s.x, s.y * s.y);
}

// The four corners of a cell (h00, h10, h01, h11): one gather.
vec4 pxCellCorners(ivec2 cell) {
    pxFetches += 1;
#if defined(PX_HAS_HARDWARE_SAMPLING)
    return pxHeightGather(cell);
#else
    ivec4 q = pxFootprint(cell);
    return vec4(pxHeightTexel(ivec2(q.x, q.z)), pxHeightTexel(ivec2(q.y, q.z)),
                pxHeightTexel(ivec2(q.x, q.w)), pxHeightTexel(ivec2(q.y, q.w)));
#endif
}

// Nothing lies above the highest texel: every march may start where the ray drops to it.
float pxStartT() {
    return clamp(1.0f - pxHeightMax, 0.0f, 1.0f);
}

// cos of the polar angle, from P = s tan(theta) dir (docs/conventions.md §5).
float pxCosTheta(vec2 P) {
    float tanTheta = pxScale > 0.0f ? length(P) / pxScale : 0.0f;
    return inversesqrt(1.0f + tanTheta * tanTheta);
}

// The tutorial shaders' quality range: maxLayers at grazing angles, minLayers looking straight down.
int pxLayerCount(vec2 P) {
    float n = pxLerp(float(pxMaxLayers), float(pxMinLayers), pxCosTheta(P));
    return max(1, int(n + 0.5f));
}

// f(t) = h(uv(t)) - (1 - t): the ray is at or below the surface where f >= 0.
float pxDepthGap(vec2 uv0, vec2 P, float t) {
    PX_PRECISE float gap = pxHeight(uv0 + P * t) - (1.0f - t);
    return gap;
}

// pxRefineSteps halvings of a bracket [lo, hi] holding one crossing (above at lo, below at hi);
// the answer is the final bracket's midpoint.
float pxBisect(vec2 uv0, vec2 P, float lo, float hi) {
    for (int i = 0; i < pxRefineSteps; ++i) {
        float mid = 0.5f * (lo + hi);
        if (pxDepthGap(uv0, P, mid) >= 0.0f)
            hi = mid;
        else
            lo = mid;
    }
    return 0.5f * (lo + hi);
}

// Smallest s in [0, sMax] with A s^2 + B s + C >= 0, given C < 0; -1 if none. Uses the
// cancellation-free form of the roots: the textbook one loses the small root when 4AC << B^2.
float pxFirstRoot(float A, float B, float C, float sMax) {
    float best = -1.0f;
    if (A == 0.0f) {
        if (B > 0.0f)
            best = -C / B;
    } else {
        float D = B * B - 4.0f * A * C;
        if (D >= 0.0f) {
            float q = -0.5f * (B + (B >= 0.0f ? sqrt(D) : -sqrt(D)));
            float r1 = q / A;
            float r2 = q != 0.0f ? C / q : -1.0f;
            float lo = min(r1, r2);
            float hi = max(r1, r2);
            best = lo >= 0.0f ? lo : hi;
        }
    }
    return (best >= 0.0f && best <= sMax) ? best : -1.0f;
}

// a * b = p.x + p.y exactly (Dekker's product with Veltkamp's split at 2^12 + 1, no fused
// multiply-add needed): on a long ray dX t reaches 10^6 cells, where a float keeps only 1/16 of a
// cell, and the bilinear patch must be read where the ray is to far better than that.
vec2 pxTwoProduct(float a, float b) {
    PX_PRECISE float p = a * b;
    PX_PRECISE float ca = 4097.0f * a;
    PX_PRECISE float ah = ca - (ca - a);
    PX_PRECISE float al = a - ah;
    PX_PRECISE float cb = 4097.0f * b;
    PX_PRECISE float bh = cb - (cb - b);
    PX_PRECISE float bl = b - bh;
    PX_PRECISE float e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    return vec2(p, e);
}

// The part of P W (cells per unit t) that rounding it to a float drops: on a ray across a million
// cells its 2^-24 is a tenth of a cell, enough to pass beside a spike the ray touches. Set by
// pxCellsPerT at the start of every trace; pxCellOffset adds it back where the position matters.
vec2 pxCellsPerTLow = vec2(0.0f, 0.0f);

// The ray's direction in cell space, dXY = (P.x W, P.y H), rounded; its remainder kept above.
vec2 pxCellsPerT(vec2 P) {
    vec2 x = pxTwoProduct(P.x, float(pxMapSize.x));
    vec2 y = pxTwoProduct(P.y, float(pxMapSize.y));
    pxCellsPerTLow = vec2(x.y, y.y);
    return vec2(x.x, y.x);
}

// X0 + dX t - cell, the ray's position at t relative to `cell`, rounded once near the cell rather
// than at the size of X: the integer parts cancel in integers (cell - floor(X0)) and against the
// exact product dX t (plus dX's remainder times t), and only the fractions are added in float.
float pxCellOffset(int cell, float X0, float dX, float dXLow, float t) {
    float i0 = floor(X0);
    vec2 p = pxTwoProduct(dX, t);
    PX_PRECISE float a = ((p.x - float(cell - int(i0))) + (p.y + dXLow * t)) + (X0 - i0);
    return a;
}

// Where the ray enters (lo) and leaves (hi) the cell on one axis, in s = t - ta, from its offset a
// in the cell at ta: exact to the rounding of a short quotient, where ta itself (a border t of a
// long ray, rounded) may lie a hundredth of a cell to either side of the border. With clamp the
// cells at and past the map's edge are constant outward, so their patch holds to infinity there
// (the pyramid's outermost nodes solve them so).
vec2 pxCellSpan(float a, float dX, int cell, int size) {
    float aLo = !pxWrapRepeat && cell <= -1 ? -PX_BIG : 0.0f;
    float aHi = !pxWrapRepeat && cell >= size - 1 ? PX_BIG : 1.0f;
    if (dX > 0.0f)
        return vec2((aLo - a) / dX, (aHi - a) / dX);
    if (dX < 0.0f)
        return vec2((aHi - a) / dX, (aLo - a) / dX);
    return vec2(-PX_BIG, PX_BIG);
}

// The exact first hit of the ray with the bilinear patch of `cell` (corner heights h00, h10, h01,
// h11) for t in [ta, tb], or -1. X0, dXY: cell-space position at t = 0 and its derivative (cells
// per unit t). On a long ray ta and tb are border t's rounded to a float, far coarser there than
// the cell: the patch is solved over the ray's own span in the cell instead, with ta and tb only
// bounding it to within a few of their ulps (PX_SPAN_SLACK), so neighbouring cells neither
// overlap nor leave a gap and the patch is never read outside its cell.
#define PX_SPAN_SLACK 4.8e-7f
float pxSolvePatch(vec4 h, ivec2 cell, vec2 X0, vec2 dXY, float ta, float tb) {
    float ax = pxCellOffset(cell.x, X0.x, dXY.x, pxCellsPerTLow.x, ta);
    float ay = pxCellOffset(cell.y, X0.y, dXY.y, pxCellsPerTLow.y, ta);
    vec2 sx = pxCellSpan(ax, dXY.x, cell.x, pxMapSize.x);
    vec2 sy = pxCellSpan(ay, dXY.y, cell.y, pxMapSize.y);
    float lo = max(max(sx.x, sy.x), -ta * PX_SPAN_SLACK);
    float hi = min(min(sx.y, sy.y), min(tb - ta + tb * PX_SPAN_SLACK, 1.0f - ta));
    if (lo > hi)
        return -1.0f;
    ax += dXY.x * lo;
    ay += dXY.y * lo;
    // The twist as the difference of the two rows' slopes: exactly 0 where the rows (or the
    // columns) are equal, as in the clamp's outermost cells, which the pyramid solves over the rest
    // of the ray at once; a rounding residue of h00 - h10 - h01 + h11 there, times dY, tilts the
    // patch by a texel.
    PX_PRECISE float k = (h.w - h.z) - (h.y - h.x);
    float hx = h.y - h.x;
    float hy = h.z - h.x;
    float C = h.x + hx * ax + hy * ay + k * ax * ay - ((1.0f - ta) - lo);
    if (C >= 0.0f)
        return ta + lo;
    float A = k * dXY.x * dXY.y;
    float B = hx * dXY.x + hy * dXY.y + k * (ax * dXY.y + ay * dXY.x) + 1.0f;
    float s = pxFirstRoot(A, B, C, hi - lo);
    return s >= 0.0f ? ta + (lo + s) : -1.0f;
}

// The same, reading the cell's corners (one fetch).
float pxSolveCell(ivec2 cell, vec2 X0, vec2 dXY, float ta, float tb) {
    return pxSolvePatch(pxCellCorners(cell), cell, X0, dXY, ta, tb);
}

// Bilinear height at offset (fx, fy) in a cell with corners h (h00, h10, h01, h11).
float pxPatchHeight(vec4 h, float fx, float fy) {
    return pxLerp(pxLerp(h.x, h.y, fx), pxLerp(h.z, h.w, fx), fy);
}

// Whether the ray at height z and offset a (pxCellOffset) in `cell`, corners h, is in the solid.
// pxCellAt reads the rounded X0 + dX t: on a long ray the exact offset can put the ray a
// thousandth of a cell into a neighbour (t a border t rounded short). There the patch is the
// neighbour's: the clamped edge of this cell put a ray that passes just above a peak in the solid
// (thousands of texels short at 89.99 degrees). Read only then, it costs no fetch otherwise.
bool pxInSolid(vec4 h, ivec2 cell, vec2 a, float z) {
    bool solid = z <= pxPatchHeight(h, clamp(a.x, 0.0f, 1.0f), clamp(a.y, 0.0f, 1.0f));
    ivec2 beside = ivec2(a.x > 1.0f ? 1 : (a.x < 0.0f ? -1 : 0),
                         a.y > 1.0f ? 1 : (a.y < 0.0f ? -1 : 0));
    if (solid && (beside.x != 0 || beside.y != 0)) {
        vec2 b = a - vec2(beside);
        solid = z <= pxPatchHeight(pxCellCorners(cell + beside), clamp(b.x, 0.0f, 1.0f),
                                   clamp(b.y, 0.0f, 1.0f));
    }
    return solid;
}

// The cell the ray occupies just after t: on a cell border, the one it is entering.
int pxCellAlong(float X, float dX) {
    return dX >= 0.0f ? int(floor(X)) : int(ceil(X)) - 1;
}

// t at which the ray, in `cell`, crosses the cell's far border on one axis (PX_BIG if parallel).
float pxBorderT(int cell, float X0, float dX) {
    if (dX > 0.0f)
        return (float(cell + 1) - X0) / dX;
    if (dX < 0.0f)
        return (float(cell) - X0) / dX;
    return PX_BIG;
}

// The cell the ray occupies just after t. Rounding can put a point that has just crossed a border
// back in the cell it left, which would stall a march there: step on past any border already
// behind t (one step per axis is enough, the rounding is far below a cell).
ivec2 pxCellAt(vec2 X0, vec2 dXY, float t) {
    ivec2 cell = ivec2(pxCellAlong(X0.x + dXY.x * t, dXY.x), pxCellAlong(X0.y + dXY.y * t, dXY.y));
    if (pxBorderT(cell.x, X0.x, dXY.x) <= t)
        cell.x += dXY.x > 0.0f ? 1 : -1;
    if (pxBorderT(cell.y, X0.y, dXY.y) <= t)
        cell.y += dXY.y > 0.0f ? 1 : -1;
    return cell;
}

// Looking straight down (or with s = 0) every technique reduces to one fetch: t = 1 - h(uv0).
float pxTraceStraightDown(vec2 uv0) {
    return 1.0f - pxHeight(uv0);
}

// The rules around every technique's trace, the one definition for the CPU tracer (Tracer.cpp)
// and the shaders (render/techniques.glsl), which each choose the technique their own way.
bool pxLooksStraightDown(vec2 P) {
    return (P.x == 0.0f && P.y == 0.0f) || pxScale == 0.0f;
}

// The kernels keep t in [0, 1]; this only guards against NaN heights reaching them.
float pxKeepT(float t) {
    return t >= 0.0f ? min(t, 1.0f) : 0.0f;
}

// The offset a ray may travel is bounded (docs/techniques.md: never divide by a z that can be 0):
// grazing views reach the bound instead of infinity, and NaN becomes a straight-down view. The
// bound is on the length, so the direction (the azimuth) is kept; infinite components give the
// direction of their signs, at the bound.
#define PX_MAX_PARALLAX 1.0e4f
vec2 pxBoundParallax(vec2 P) {
    vec2 q = vec2(isnan(P.x) ? 0.0f : P.x, isnan(P.y) ? 0.0f : P.y);
    if (isinf(q.x) || isinf(q.y))
        q = vec2(isinf(q.x) ? sign(q.x) * PX_MAX_PARALLAX : 0.0f,
                 isinf(q.y) ? sign(q.y) * PX_MAX_PARALLAX : 0.0f);
    float big = max(abs(q.x), abs(q.y));
    if (big <= PX_MAX_PARALLAX * 0.5f)
        return q; // well inside the bound (and length() cannot overflow)
    vec2 unit = q / big; // components in [-1, 1]: length() cannot overflow
    float len = length(unit) * big;
    return len > PX_MAX_PARALLAX ? unit * (PX_MAX_PARALLAX / length(unit)) : q;
}

// `cone`: conservative cone stepping (Dummer 2006) that never steps through the surface. A cone
// interpolated between texels is no cone of the surface: at a needle's tip a grazing ray stepped by
// it goes straight through. The cones baked at the four corners of the ray's cell are
// (docs/conventions.md §4: no point of the bilinear surface inside them), so the ray steps as far
// as it stays inside any one of them. Where that does not leave the cell, the cell is solved
// exactly. Where the step cap runs out, the ray is still above the surface: the cell walk finishes
// it (pxFinishExact), so every ray ends on the exact hit.

struct PxConeCorners {
    vec4 h; // heights h00, h10, h01, h11
    vec4 c; // cone ratios, same order
};

// The four corner texels of a cell in the cone map: one gather.
PxConeCorners pxConeCorners(ivec2 cell) {
    pxFetches += 1;
    PxConeCorners k;
#if defined(PX_HAS_HARDWARE_SAMPLING)
    k.h = pxConeGatherHeights(cell);
    vec4 r = pxConeGatherRoots(cell);
    k.c = vec4(r.x * r.x, r.y * r.y, r.z * r.z, r.w * r.w);
#else
    ivec4 q = pxFootprint(cell);
    vec2 a = pxConeTexel(ivec2(q.x, q.z));
    vec2 b = pxConeTexel(ivec2(q.y, q.z));
    vec2 d = pxConeTexel(ivec2(q.x, q.w));
    vec2 e = pxConeTexel(ivec2(q.y, q.w));
    k.h = vec4(a.x, b.x, d.x, e.x);
    k.c = vec4(a.y * a.y, b.y * b.y, d.y * d.y, e.y * e.y);
#endif
    return k;
}

// How far in t a ray at `uv`, height z, stays inside the upward cone with apex (apex, h) and ratio
// c: |uv + P s - apex| <= c (z - s - h). The cone is convex, so that is up to its first exit, a
// root of (|P|^2 - c^2) s^2 + 2 (d.P + c A) s + |d|^2 - A^2 with A = c (z - h). 0 if not inside.
// d is the ray's horizontal offset from the apex, uv - apex.
float pxConeExitFrom(vec2 d, float h, float c, vec2 P, float z) {
    float A = c * (z - h);
    float k = dot(d, d) - A * A;
    if (!(A > 0.0f) || k >= 0.0f)
        return 0.0f;
    float s = pxFirstRoot(dot(P, P) - c * c, 2.0f * (dot(d, P) + c * A), k, z - h);
    return s >= 0.0f ? s : z - h; // inside all the way down to the apex's height
}

// A step ends where its cone lets the ray out, which on a tight cone is where the ray meets the
// surface. t + step rounds to a float's last bit of t, on a long grazing ray a thousandth of a cell
// and more: the sum can land past that meeting, through the tip of a wall whose ridge the ray
// clips (seed 71092, walls, 89.99 degrees: 39 texels late) or inside the solid. So a step lands
// this far short of its rounded end (8 to 16 of t's ulps), still above the surface; a step whose
// landing would not leave the cell solves the cell exactly instead, as a short step does.
#define PX_CONE_LANDING (1.0f - 4.0f * PX_SPAN_SLACK)

float pxTraceCone(vec2 uv0, vec2 P) {
    vec2 X0 = pxCellCoords(uv0);
    vec2 dXY = pxCellsPerT(P);
    float t = pxStartT();
    float tAbove = t; // the last t known above the surface
    for (int i = 0; i < pxMaxSteps; ++i) {
        ivec2 cell = pxCellAt(X0, dXY, t);
        float tCell = min(min(pxBorderT(cell.x, X0.x, dXY.x), pxBorderT(cell.y, X0.y, dXY.y)), 1.0f);
        PxConeCorners k = pxConeCorners(cell);
        // The ray's offset from the cell's first corner, in texels, from the cell-relative
        // position (pxCellOffset): uv0 + P t is hundreds of uv out on a long ray, where a float's
        // last bit is a thousandth of a texel, enough to step just past a wall's face.
        vec2 a = vec2(pxCellOffset(cell.x, X0.x, dXY.x, pxCellsPerTLow.x, t),
                      pxCellOffset(cell.y, X0.y, dXY.y, pxCellsPerTLow.y, t));
        float z = 1.0f - t;
        // A border t rounded up (the step onto it above) can put the ray just past a crossing, in
        // the solid: no cone holds such a point, but one touching the face there may by rounding.
        if (pxInSolid(k.h, cell, a, z))
            return pxCrossingBefore(X0, dXY, tAbove, t);
        tAbove = t;
        float step = 0.0f;
        for (int j = 0; j < 4; ++j) {
            ivec2 texel = ivec2(cell.x + (j & 1), cell.y + (j >> 1));
            // With clamp, texels past the edge repeat the edge's data at another place: no cone.
            bool inside = texel.x >= 0 && texel.y >= 0 && texel.x < pxMapSize.x && texel.y < pxMapSize.y;
            if (pxWrapRepeat || inside) {
                vec2 d = vec2((a.x - float(j & 1)) / float(pxMapSize.x),
                              (a.y - float(j >> 1)) / float(pxMapSize.y));
                step = max(step, pxConeExitFrom(d, k.h[j], k.c[j], P, z));
            }
        }
        float tEnd = t + step;
        float tLand = tEnd * PX_CONE_LANDING;
        if (tLand < tCell) {
            float root = pxSolvePatch(k.h, cell, X0, dXY, t, tCell);
            if (root >= 0.0f)
                return root;
            t = max(t, tCell);
        } else if (tEnd >= 1.0f) {
            return 1.0f; // f(1) >= 0: the bottom is always solid
        } else {
            t = tLand;
        }
        if (t >= 1.0f)
            return 1.0f;
    }
    return pxFinishExact(X0, dXY, t); // the cap ran out above the surface
}

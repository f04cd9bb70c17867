// `relaxed-cone`: relaxed cone stepping (Policarpo & Oliveira, GPU Gems 3 ch. 18), exact on every
// ray. A relaxed cone at texel b lets a ray enter the solid but not leave it, and only for rays
// from b's column: inside it no surface point falls away from b (docs/cone-maps.md §1). A cone
// interpolated at the ray's position is no such cone (a grazing step passed through needles and
// terraces' edges and out again). So the ray steps only as far as it stays inside the cones of all
// three corners of a triangle of its cell that holds its position p: a point q inside them falls
// away from none of the three, and q - p, a convex combination of the q - b, does not fall either,
// so the ray cannot leave the solid in the step. Of the cell's two triangulations it takes the one
// that steps further. Where the step would not leave the cell, the cell is solved exactly
// (docs/cone-maps.md §1, "a minimum step"): zero cones cannot stall the march.
//
// A step that ends in the solid crossed the surface once: its cells are solved exactly (halvings
// would keep any crossing). A march whose cap runs out is finished by the cell walk from the last
// point known above the surface.

float pxTraceRelaxedCone(vec2 uv0, vec2 P) {
    vec2 X0 = pxCellCoords(uv0);
    vec2 dXY = pxCellsPerT(P);
    vec2 texelUv = vec2(1.0f / float(pxMapSize.x), 1.0f / float(pxMapSize.y));
    float t = pxStartT();
    float tAbove = t; // the last t known above the surface
    for (int i = 0; i < pxMaxSteps; ++i) {
        ivec2 cell = pxCellAt(X0, dXY, t);
        float tCell = min(min(pxBorderT(cell.x, X0.x, dXY.x), pxBorderT(cell.y, X0.y, dXY.y)), 1.0f);
        PxConeCorners k = pxConeCorners(cell);
        // The ray's offset in the cell, from the exact product (long rays keep the texel).
        vec2 a = vec2(pxCellOffset(cell.x, X0.x, dXY.x, pxCellsPerTLow.x, t),
                       pxCellOffset(cell.y, X0.y, dXY.y, pxCellsPerTLow.y, t));
        float z = 1.0f - t;
        if (pxInSolid(k.h, cell, a, z))
            return pxCrossingBefore(X0, dXY, tAbove, t); // the last step crossed once
        vec4 e = vec4(0.0f, 0.0f, 0.0f, 0.0f);
        for (int j = 0; j < 4; ++j) {
            ivec2 texel = ivec2(cell.x + (j & 1), cell.y + (j >> 1));
            // With clamp, texels past the edge repeat the edge's data at another place: no cone.
            bool inside = texel.x >= 0 && texel.y >= 0 && texel.x < pxMapSize.x && texel.y < pxMapSize.y;
            if (pxWrapRepeat || inside) {
                vec2 d = vec2((a.x - float(j & 1)) * texelUv.x, (a.y - float(j >> 1)) * texelUv.y);
                e[j] = pxConeExitFrom(d, k.h[j], k.c[j], P, z);
            }
        }
        // Diagonal h00-h11: p lies in (00, 10, 11) or (00, 01, 11); diagonal h10-h01: in
        // (00, 10, 01) or (10, 01, 11).
        float onMain = min(min(e.x, e.w), a.x >= a.y ? e.y : e.z);
        float onAnti = min(min(e.y, e.z), a.x + a.y <= 1.0f ? e.x : e.w);
        float step = max(onMain, onAnti);
        if (t + step < tCell) {
            float root = pxSolvePatch(k.h, cell, X0, dXY, t, tCell);
            if (root >= 0.0f)
                return root;
            t = max(t, tCell);
            tAbove = t;
        } else {
            tAbove = t;
            t = min(t + step, 1.0f);
        }
        if (t >= 1.0f) // the bottom is solid (f(1) >= 0): the first crossing lies after tAbove
            return pxCrossingBefore(X0, dXY, tAbove, 1.0f);
    }
    return pxFinishExact(X0, dXY, tAbove); // the cap ran out: walk on from where it was above
}

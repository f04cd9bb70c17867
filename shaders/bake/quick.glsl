// Quick conservative cone maps (Valasek & Bán 2022, docs/cone-maps.md §2) for the bilinear
// surface: per texel, 3 x 3 blocks of max-pyramid nodes around it, level by level, each node
// bounded by its maximum at the nearest point not already checked (region growing). Θ(N² log N),
// conservative because every cell meets a node whose maximum is at least its own, no nearer.
// A node's bound is worked out (square roots, a division) only where its squared form says it
// may narrow the cone: the same cones as computing every bound.
//
// Bindings:
//   int pxCellLevels                      levels of the cells' maximum pyramid (level 0: cells)
//   ivec2 pxCellSize(int level)
//   float pxCellMax(int level, ivec2 n)

// Squared distance from the apex to the nearest point of rectangle n (texels, relative to the
// apex: x0, x1, y0, y1) outside rectangle c, which holds the apex: n minus c is covered by n
// clipped to the four half-planes outside c's sides. .x: the squared distance (PX_BAKE_FAR if
// none), .yz: the offsets it is from.
vec3 pxQuickOutside(vec4 n, vec4 c) {
    vec3 best = vec3(PX_BAKE_FAR, 0.0f, 0.0f);
    float nx = pxBakeGap(n.x, n.y), ny = pxBakeGap(n.z, n.w);
    if (n.x < c.x) {
        float gx = pxBakeGap(n.x, min(n.y, c.x));
        float d2 = pxBakeDistance2(gx, ny);
        if (d2 < best.x)
            best = vec3(d2, gx, ny);
    }
    if (n.y > c.y) {
        float gx = pxBakeGap(max(n.x, c.y), n.y);
        float d2 = pxBakeDistance2(gx, ny);
        if (d2 < best.x)
            best = vec3(d2, gx, ny);
    }
    if (n.z < c.z) {
        float gy = pxBakeGap(n.z, min(n.w, c.z));
        float d2 = pxBakeDistance2(nx, gy);
        if (d2 < best.x)
            best = vec3(d2, nx, gy);
    }
    if (n.w > c.w) {
        float gy = pxBakeGap(max(n.z, c.w), n.w);
        float d2 = pxBakeDistance2(nx, gy);
        if (d2 < best.x)
            best = vec3(d2, nx, gy);
    }
    return best;
}

// The cone c narrowed by a region at gap (gx, gy) (squared distance d2) whose maximum rises
// `rise` above the apex: min(c, distance / rise), the division only where it may narrow.
float pxQuickNarrow(float c, float d2, float gx, float gy, float rise) {
    PX_PRECISE float reach2 = c * c * rise * rise * (1.0f + 1.0e-5f);
    if (!(d2 < reach2))
        return c;
    PX_PRECISE float bound = pxBakeDistance(gx, gy) / rise;
    return min(c, bound);
}

// One axis of the checked block: its cells [first, last] (extended indices with repeat).
ivec2 pxQuickClip(ivec2 s, int cells) {
    if (pxBakeRepeat)
        return s;
    return ivec2(max(s.x, 0), min(s.y, cells - 1));
}

// The period of extended node e, -1 <= e <= nodes (the neighbours of a node of the map).
int pxQuickPeriod(int e, int nodes) {
    return e < 0 ? -1 : (e >= nodes ? 1 : 0);
}

// The cells of extended node e at `level` with `nodes` nodes over `cells` cells per period: node
// e mod nodes, shifted by whole periods.
ivec2 pxQuickNodeCells(int e, int level, int nodes, int cells) {
    int period = pxQuickPeriod(e, nodes);
    int a = e - period * nodes;
    return ivec2(period * cells + (a << level), period * cells + min((a + 1) << level, cells) - 1);
}

// The cells of nodes a - 1 .. a + 1 at `level`.
ivec2 pxQuickBlock(int a, int level, int nodes, int cells) {
    int lo = a - 1, hi = a + 1;
    if (!pxBakeRepeat) {
        lo = max(lo, 0);
        hi = min(hi, nodes - 1);
    }
    return ivec2(pxQuickNodeCells(lo, level, nodes, cells).x,
                 pxQuickNodeCells(hi, level, nodes, cells).y);
}

// The block of cells sx x sy as a texel rectangle relative to apex b.
vec4 pxQuickRect(ivec2 sx, ivec2 sy, ivec2 b) {
    ivec2 span = pxBakeSpan();
    return vec4(float(sx.x - b.x), float(sx.y + span.x - b.x), float(sy.x - b.y),
                float(sy.y + span.y - b.y));
}

// Early stop: every cell outside the checked block is at least `d` away and at most the map's
// maximum high, so it cannot narrow the cone once d / (max - h_b) >= c (here squared, with a
// margin: it may stop later, never earlier). With clamp a side at the map's edge has nothing
// beyond it.
bool pxQuickDone(ivec2 b, float hb, ivec2 sx, ivec2 sy, float c) {
    ivec2 cells = pxBakeCells();
    float d2 = PX_BAKE_FAR;
    if (pxBakeRepeat || sx.x > 0)
        d2 = min(d2, pxBakeDistance2(float(b.x - sx.x), 0.0f));
    if (pxBakeRepeat || sx.y < cells.x - 1)
        d2 = min(d2, pxBakeDistance2(float(sx.y + 1 - b.x), 0.0f));
    if (pxBakeRepeat || sy.x > 0)
        d2 = min(d2, pxBakeDistance2(0.0f, float(b.y - sy.x)));
    if (pxBakeRepeat || sy.y < cells.y - 1)
        d2 = min(d2, pxBakeDistance2(0.0f, float(sy.y + 1 - b.y)));
    if (d2 == PX_BAKE_FAR)
        return true;
    PX_PRECISE float rise = pxBakeMax - hb;
    PX_PRECISE float reach2 = c * c * rise * rise * (1.0f + 1.0e-5f);
    return d2 >= reach2;
}

// The raw conservative cone (not finished) of texel b.
float pxQuickCone(ivec2 b) {
    float hb = pxBakeTexel(b);
    if (!(hb < pxBakeMax))
        return 1.0f; // nothing rises above the apex
    ivec2 cells = pxBakeCells();
    ivec2 span = pxBakeSpan();
    float c = 1.0f;
    // Level 0: the 3 x 3 cells around cell b; the four with b as a corner exactly (the plain
    // bound would be 0 there), the others by their maximum at their nearest point.
    for (int oy = -1; oy <= 1; ++oy) {
        for (int ox = -1; ox <= 1; ++ox) {
            if (!pxBakeRepeat && (b.x + ox < 0 || b.x + ox >= cells.x || b.y + oy < 0 ||
                                  b.y + oy >= cells.y))
                continue;
            ivec2 o = ivec2(ox, oy);
            if (pxBakeIsApexCell(o, span)) {
                c = min(c, pxBakeFloatDown(pxBakeApexConservative(b, double(hb), o, span)));
                continue;
            }
            float m = pxCellMax(0, ivec2(pxBakeResolve(b.x + ox, cells.x),
                                         pxBakeResolve(b.y + oy, cells.y)));
            if (m > hb) {
                float gx = pxBakeGap(float(ox), float(ox + span.x));
                float gy = pxBakeGap(float(oy), float(oy + span.y));
                c = pxQuickNarrow(c, pxBakeDistance2(gx, gy), gx, gy, m - hb);
            }
        }
    }
    ivec2 sx = pxQuickClip(ivec2(b.x - 1, b.x + 1), cells.x);
    ivec2 sy = pxQuickClip(ivec2(b.y - 1, b.y + 1), cells.y);
    for (int level = 1; level < pxCellLevels && !pxQuickDone(b, hb, sx, sy, c); ++level) {
        ivec2 nodes = pxCellSize(level);
        int ax = b.x >> level, ay = b.y >> level;
        vec4 checked = pxQuickRect(sx, sy, b);
        for (int ey = ay - 1; ey <= ay + 1; ++ey) {
            if (!pxBakeRepeat && (ey < 0 || ey >= nodes.y))
                continue;
            for (int ex = ax - 1; ex <= ax + 1; ++ex) {
                if ((ex == ax && ey == ay) || (!pxBakeRepeat && (ex < 0 || ex >= nodes.x)))
                    continue; // the centre node lies inside the previous block
                float m = pxCellMax(level, ivec2(ex - pxQuickPeriod(ex, nodes.x) * nodes.x,
                                                 ey - pxQuickPeriod(ey, nodes.y) * nodes.y));
                if (!(m > hb))
                    continue;
                ivec2 cx = pxQuickNodeCells(ex, level, nodes.x, cells.x);
                ivec2 cy = pxQuickNodeCells(ey, level, nodes.y, cells.y);
                vec3 d = pxQuickOutside(pxQuickRect(cx, cy, b), checked);
                if (d.x < PX_BAKE_FAR)
                    c = pxQuickNarrow(c, d.x, d.y, d.z, m - hb);
            }
        }
        sx = pxQuickBlock(ax, level, nodes.x, cells.x);
        sy = pxQuickBlock(ay, level, nodes.y, cells.y);
    }
    return c;
}

// What the map stores for texel b: sqrt of the finished ratio.
float pxQuickResult(ivec2 b) {
    PX_PRECISE float g = sqrt(pxBakeFinish(pxQuickCone(b)));
    return g;
}

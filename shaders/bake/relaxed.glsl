// Relaxed cone maps, safe for the bilinear surface (docs/cone-maps.md §1): the cone of apex b is
// the least bound pxBakeRelaxedAt() gives over every cell (and, with clamp, every edge strip),
// found by a branch and bound over a maximum pyramid of the cells that can fall at all. A node
// holds the highest of its non-flat cells and the box of their gradients; it is skipped for an
// apex it is too far from, too low for, or that no gradient of the box falls away from (exact in
// integers). Apexes go in 4 x 4 tiles that share one traversal, each apex keeping the mask bit of
// the nodes still open for it. The cells' bounds do not depend on the order they are met in, so
// the cone is the same whatever the search (the ring scan's, the CPU's seeded from the
// neighbouring tiles, the GPU's unseeded).
//
// Bindings:
//   int pxFallTop                         the top level (0 for a one-cell map)
//   ivec2 pxFallSize(int level)           nodes per level (level 0: the cells)
//   uvec3 pxFallNode(int level, ivec2 n)  level >= 1: (q | s << 16, gx0 | gx1 << 16,
//                                         gy0 | gy1 << 16): the highest non-flat cell's corner
//                                         is at most q pxFallUnit (q = 0: none), the box of the
//                                         cells' corner differences scaled by 2^(s - 128),
//                                         16-bit signed, rounded outwards (only signs matter)
//   float pxFallUnit

#define PX_TILE_W 4
#define PX_TILE_H 4
#define PX_TILE_APEXES 16
#define PX_NODE_STACK 96
// Node bounds keep a relative margin so that a node is skipped only where every cell of it
// certainly cannot narrow the cone (its own bound compares in the same float arithmetic).
#define PX_NODE_MARGIN (1.0f + 1.0e-5f)

// The tile: apex texels, heights, cones so far (and their squares with the margin), and the cell
// that last narrowed each cone (.xy, extended coordinates; .z = 1 if there is one).
int pxTileCount;
int pxTileX[PX_TILE_APEXES];
int pxTileY[PX_TILE_APEXES];
float pxTileH[PX_TILE_APEXES];
float pxTileC[PX_TILE_APEXES];
float pxTileReach[PX_TILE_APEXES];
ivec3 pxTileWitness[PX_TILE_APEXES];
// The tile as a whole: its texel box (x0, x1, y0, y1), lowest apex and widest cone so far.
ivec4 pxTileBox;
float pxTileHMin;
float pxTileCMax;
// Seeds, cells tried first: the witnesses of the tile to the left (per row) and above (per
// column), .z = 0 where there are none.
ivec3 pxSeedRow[PX_TILE_H];
ivec3 pxSeedColumn[PX_TILE_W];

ivec4 pxNodeStack[PX_NODE_STACK]; // (level, x, y, period: px + 1 + 3 (py + 1))
uint pxMaskStack[PX_NODE_STACK];

// Apex k's cone becomes f, set by `cell`, if that is narrower.
void pxRelaxedNarrow(int k, float f, ivec2 cell) {
    if (f < pxTileC[k]) {
        pxTileC[k] = f;
        PX_PRECISE float reach = f * f * PX_NODE_MARGIN;
        pxTileReach[k] = reach;
        pxTileWitness[k] = ivec3(cell, 1);
    }
}

// Whether cell offset o from an apex is one the searches may look at: inside the map (clamp) or
// less than a period away (repeat).
bool pxRelaxedValid(ivec2 b, ivec2 o) {
    if (pxBakeRepeat)
        return !pxBakeBeyondPeriod(o.x, o.y);
    ivec2 cells = pxBakeCells();
    return b.x + o.x >= 0 && b.x + o.x < cells.x && b.y + o.y >= 0 && b.y + o.y < cells.y;
}

// Narrows apex k's cone with the cell whose top-left texel is `cell` (extended coordinates).
void pxRelaxedTry(int k, ivec2 cell) {
    ivec2 b = ivec2(pxTileX[k], pxTileY[k]);
    ivec2 o = cell - b;
    if (pxRelaxedValid(b, o))
        pxRelaxedNarrow(k, pxBakeRelaxedAt(b, pxTileH[k], o, pxBakeSpan(), pxTileC[k]), cell);
}

// The texel rectangle (x0, x1, y0, y1) the cells of node n cover, far corners included, in
// extended coordinates.
ivec4 pxRelaxedNodeRect(ivec4 n) {
    ivec2 cells = pxBakeCells();
    ivec2 span = pxBakeSpan();
    int period = n.w;
    int baseX = (period % 3 - 1) * cells.x;
    int baseY = (period / 3 - 1) * cells.y;
    int size = 1 << n.x;
    return ivec4(baseX + n.y * size, baseX + min((n.y + 1) * size, cells.x) - 1 + span.x,
                 baseY + n.z * size, baseY + min((n.z + 1) * size, cells.y) - 1 + span.y);
}

// A node's highest corner (-PX_BAKE_FAR if it has no cell that falls).
float pxRelaxedTop(uvec3 data) {
    uint q = data.x & 65535u;
    if (q == 0u)
        return -PX_BAKE_FAR;
    PX_PRECISE float m = float(q) * pxFallUnit;
    return m;
}

// The box of a node's gradients (data: pxFallNode()), (gx0, gx1, gy0, gy1), from its 16-bit
// halves, sign-extended (shifts: GLM's bitfieldExtract does not extend signs).
ivec4 pxRelaxedGradients(uvec3 data) {
    return ivec4((int(data.y) << 16) >> 16, int(data.y) >> 16, (int(data.z) << 16) >> 16,
                 int(data.z) >> 16);
}

// Whether some gradient of box g falls away from an apex at some point of the rectangle
// [x0, x1] x [y0, y1] (texels, relative to the apex): g . (q - b) < 0, smallest at corners of both
// boxes, separately in x and y; exact in integers.
bool pxRelaxedFalls(ivec4 g, int x0, int x1, int y0, int y1) {
    int dx = min(min(g.x * x0, g.x * x1), min(g.y * x0, g.y * x1));
    int dy = min(min(g.z * y0, g.z * y1), min(g.w * y0, g.w * y1));
    return dx + dy < 0;
}

// Node n (level >= 1, gradients g, rectangle r, highest corner m) for the tile as a whole: from
// the tile box's nearest point, its lowest apex and its widest cone, the node's priority (the
// smaller the nearer; PX_BAKE_FAR: it narrows no cone of the tile). Nodes far from the tile are
// so skipped for all of its apexes at once.
// The tile box's squared distance to the last node pxRelaxedTileBound() passed, and whether the
// node is many tiles away (PX_FAR_TILES tile sizes or more along an axis).
float pxTileD2;
bool pxTileFar;
#define PX_FAR_TILES 8

float pxRelaxedTileBound(ivec4 g, ivec4 r, float m) {
    PX_PRECISE float rise = m - pxTileHMin;
    if (!(rise > 0.0f))
        return PX_BAKE_FAR;
    int x0 = r.x - pxTileBox.y, x1 = r.y - pxTileBox.x;
    int y0 = r.z - pxTileBox.w, y1 = r.w - pxTileBox.z;
    int gapX = pxBakeGapInt(x0, x1);
    int gapY = pxBakeGapInt(y0, y1);
    if (pxBakeRepeat && (gapX >= pxBakeSize.x || gapY >= pxBakeSize.y))
        return PX_BAKE_FAR;
    PX_PRECISE float d2 = pxBakeDistance2(float(gapX), float(gapY));
    PX_PRECISE float reach2 = pxTileCMax * pxTileCMax * rise * rise * PX_NODE_MARGIN;
    if (d2 >= reach2 || !pxRelaxedFalls(g, x0, x1, y0, y1))
        return PX_BAKE_FAR;
    pxTileD2 = d2;
    // (Cells a period or more away from an apex are skipped at the leaves.)
    pxTileFar = max(gapX, gapY) >= PX_FAR_TILES * PX_TILE_W;
    return d2 / reach2;
}

// The apexes of `mask` that node n (level >= 1, gradients g, rectangle r, highest corner m) may
// narrow: rising above the apex within its cone's reach, and falling away from it. `tileD2` is
// the squared distance from the tile's box (at most each apex's): for a node many tiles away the
// apexes' own distances and directions differ little from the box's, so only their heights and
// cones are compared, against it (a looser test, never a wrong skip).
uint pxRelaxedOpen(ivec4 n, ivec4 g, ivec4 r, float m, uint mask, float tileD2, bool far) {
    uint open = 0u;
    if (far) {
        for (uint bits = mask; bits != 0u; bits &= bits - 1u) {
            int k = findLSB(bits);
            PX_PRECISE float rise = m - pxTileH[k];
            PX_PRECISE float reach2 = pxTileReach[k] * rise * rise;
            if (rise > 0.0f && tileD2 < reach2)
                open |= 1u << uint(k);
        }
        return open;
    }
    // Only a neighbouring period's node can be a period or more away from an apex.
    bool periods = pxBakeRepeat && n.w != 4;
    int rx0 = r.x, rx1 = r.y, ry0 = r.z, ry1 = r.w;
    for (uint bits = mask; bits != 0u; bits &= bits - 1u) {
        int k = findLSB(bits);
        PX_PRECISE float rise = m - pxTileH[k];
        if (!(rise > 0.0f))
            continue;
        int x0 = rx0 - pxTileX[k], x1 = rx1 - pxTileX[k];
        int y0 = ry0 - pxTileY[k], y1 = ry1 - pxTileY[k];
        int gapX = pxBakeGapInt(x0, x1);
        int gapY = pxBakeGapInt(y0, y1);
        if (periods && (gapX >= pxBakeSize.x || gapY >= pxBakeSize.y))
            continue;
        PX_PRECISE float d2 = pxBakeDistance2(float(gapX), float(gapY));
        PX_PRECISE float reach2 = pxTileReach[k] * rise * rise;
        if (d2 < reach2 && pxRelaxedFalls(g, x0, x1, y0, y1))
            open |= 1u << uint(k);
    }
    return open;
}

// A leaf: the cells of node n (level 1: up to 2 x 2; level 0: the one cell of a one-cell map), for
// each apex of `mask`.
void pxRelaxedLeaf(ivec4 n, uint mask) {
    ivec2 cells = pxBakeCells();
    ivec2 span = pxBakeSpan();
    ivec4 r = pxRelaxedNodeRect(n);
    int step = n.x == 1 ? 2 : 1;
    for (int j = 0; j < step; ++j) {
        for (int i = 0; i < step; ++i) {
            int cx = n.y * step + i, cy = n.z * step + j;
            if (cx >= cells.x || cy >= cells.y)
                continue;
            ivec2 cell = ivec2(r.x + i, r.z + j);
            vec4 k = pxBakeCorners(cell, span);
            if (k.x == k.y && k.x == k.z && k.x == k.w)
                continue; // flat: falls nowhere
            float top = pxBakeMax4(k);
            for (uint bits = mask; bits != 0u; bits &= bits - 1u) {
                int a = findLSB(bits);
                ivec2 o = ivec2(cell.x - pxTileX[a], cell.y - pxTileY[a]);
                if ((abs(o.x) <= 1 && abs(o.y) <= 1) || pxBakeBeyondPeriod(o.x, o.y))
                    continue; // the 3 x 3 around the apex were tried first
                PX_PRECISE float rise = top - pxTileH[a];
                if (!(rise > 0.0f))
                    continue;
                PX_PRECISE float d2 = pxBakeDistance2(pxBakeGap(float(o.x), float(o.x + span.x)),
                                                      pxBakeGap(float(o.y), float(o.y + span.y)));
                PX_PRECISE float reach2 = pxTileReach[a] * rise * rise;
                if (d2 < reach2) {
                    ivec2 b = ivec2(pxTileX[a], pxTileY[a]);
                    pxRelaxedNarrow(a, pxBakeRelaxedCell(b, pxTileH[a], o, span, k, pxTileC[a]),
                                    cell);
                }
            }
        }
    }
}

// Pushes node n (level >= 1) if it may narrow the cone of an apex of `mask`, keeping the nodes
// pushed since `first` ordered by their priority in `order`, the nearest last (popped first).
// Returns the new stack top.
float pxNodeOrder[9];
int pxRelaxedPush(ivec4 n, uint mask, int first, int top) {
    uvec3 data = pxFallNode(n.x, ivec2(n.y, n.z));
    float m = pxRelaxedTop(data);
    ivec4 g = pxRelaxedGradients(data);
    ivec4 r = pxRelaxedNodeRect(n);
    float priority = pxRelaxedTileBound(g, r, m);
    if (priority == PX_BAKE_FAR)
        return top;
    uint open = pxRelaxedOpen(n, g, r, m, mask, pxTileD2, pxTileFar);
    if (open == 0u)
        return top;
    int at = top;
    while (at > first && pxNodeOrder[at - first - 1] < priority) {
        pxNodeStack[at] = pxNodeStack[at - 1];
        pxMaskStack[at] = pxMaskStack[at - 1];
        pxNodeOrder[at - first] = pxNodeOrder[at - first - 1];
        at -= 1;
    }
    pxNodeStack[at] = n;
    pxMaskStack[at] = open;
    pxNodeOrder[at - first] = priority;
    return top + 1;
}

// The branch and bound over the pyramid for the apexes of `all`, nearest nodes first.
void pxRelaxedSearch(uint all) {
    // The roots: the whole map, and with repeat its neighbouring periods.
    pxTileCMax = 0.0f;
    for (uint bits = all; bits != 0u; bits &= bits - 1u)
        pxTileCMax = max(pxTileCMax, pxTileC[findLSB(bits)]);
    int top = 0;
    int periods = pxBakeRepeat ? 1 : 0;
    for (int py = -periods; py <= periods; ++py) {
        for (int px = -periods; px <= periods; ++px) {
            ivec4 root = ivec4(pxFallTop, 0, 0, px + 1 + 3 * (py + 1));
            if (pxFallTop > 0) {
                top = pxRelaxedPush(root, all, 0, top);
            } else {
                pxNodeStack[top] = root;
                pxMaskStack[top] = all;
                top += 1;
            }
        }
    }
    while (top > 0) {
        top -= 1;
        ivec4 n = pxNodeStack[top];
        uint mask = pxMaskStack[top];
        if (n.x <= 1) {
            pxRelaxedLeaf(n, mask);
            continue;
        }
        // The tile's widest cone may have narrowed since the node was pushed.
        pxTileCMax = 0.0f;
        for (uint bits = mask; bits != 0u; bits &= bits - 1u)
            pxTileCMax = max(pxTileCMax, pxTileC[findLSB(bits)]);
        int level = n.x - 1;
        ivec2 size = pxFallSize(level);
        int first = top;
        for (int j = 0; j < 2; ++j) {
            for (int i = 0; i < 2; ++i) {
                ivec4 child = ivec4(level, 2 * n.y + i, 2 * n.z + j, n.w);
                if (child.y < size.x && child.z < size.y)
                    top = pxRelaxedPush(child, mask, first, top);
            }
        }
    }
}

// The raw relaxed cones (not finished) of the tile with top-left texel `origin` and `size`
// texels, in pxTileC (row by row), with the cells that set them in pxTileWitness.
void pxRelaxedTile(ivec2 origin, ivec2 size) {
    pxTileCount = size.x * size.y;
    pxTileBox = ivec4(origin.x, origin.x + size.x - 1, origin.y, origin.y + size.y - 1);
    pxTileHMin = PX_BAKE_FAR;
    uint all = 0u;
    for (int k = 0; k < pxTileCount; ++k) {
        int i = k % size.x, j = k / size.x;
        ivec2 b = ivec2(origin.x + i, origin.y + j);
        pxTileX[k] = b.x;
        pxTileY[k] = b.y;
        pxTileH[k] = pxBakeTexel(b);
        pxTileC[k] = 1.0f;
        pxTileReach[k] = PX_NODE_MARGIN;
        pxTileWitness[k] = ivec3(0, 0, 0);
        if (!(pxTileH[k] < pxBakeMax))
            continue; // nothing rises above the apex
        if (pxSeedRow[j].z != 0)
            pxRelaxedTry(k, ivec2(pxSeedRow[j].x, pxSeedRow[j].y));
        if (pxSeedColumn[i].z != 0)
            pxRelaxedTry(k, ivec2(pxSeedColumn[i].x, pxSeedColumn[i].y));
        // The 3 x 3 cells around the apex (the four with b as a corner are exact).
        for (int oy = -1; oy <= 1; ++oy) {
            for (int ox = -1; ox <= 1; ++ox)
                pxRelaxedTry(k, ivec2(b.x + ox, b.y + oy));
        }
        pxTileHMin = min(pxTileHMin, pxTileH[k]);
        all |= 1u << uint(k);
    }
    if (all != 0u)
        pxRelaxedSearch(all);
    for (int k = 0; k < pxTileCount; ++k) {
        if ((all & (1u << uint(k))) != 0u && !pxBakeRepeat)
            pxTileC[k] = pxStripsNarrow(ivec2(pxTileX[k], pxTileY[k]), pxTileH[k], pxTileC[k]);
    }
}

// What the map stores for apex k of the tile: sqrt of the finished ratio.
float pxRelaxedResult(int k) {
    PX_PRECISE float g = sqrt(pxBakeFinish(pxTileC[k]));
    return g;
}

// `pyramid`: maximum-mipmap traversal (Tevs, Ihrke, Seidel 2008), stackless. Level 0 bounds each
// cell by the max of its four corners (a bilinear patch never exceeds them); level L+1 is the max
// of its children, sizes rounded up. The ray skips every node whose box top it passes over and
// ends in the same exact cell solve as `exact`, so it finds the same hit.
//
// Layout of level 0: repeat, W x H cells (cell c uses texels c and c+1 mod W); clamp, (W+1) x (H+1)
// cells for c = -1 .. W-1, the outermost ones stretched to infinity so rays that leave [0,1] see
// the clamped edge. With repeat, nodes never straddle a tile seam: any size works.

float pxMaxMip(int level, ivec2 node) {
    pxFetches += 1;
    return pxMaxMipNode(level, node);
}

int pxNodeOf(int cell, int level, int size) {
    if (pxWrapRepeat)
        return (cell - size * pxFloorDiv(cell, size)) >> level;
    return clamp(cell + 1, 0, size) >> level;
}

// The cells [lo, hi) a node covers on one axis, in unbounded cell coordinates.
vec2 pxNodeSpan(int cell, int level, int size) {
    if (pxWrapRepeat) {
        int tile = size * pxFloorDiv(cell, size);
        int n = (cell - tile) >> level;
        return vec2(float(tile + (n << level)), float(tile + min((n + 1) << level, size)));
    }
    int n = clamp(cell + 1, 0, size) >> level;
    float lo = n == 0 ? -PX_BIG : float((n << level) - 1);
    float hi = ((n + 1) << level) >= size + 1 ? PX_BIG : float(((n + 1) << level) - 1);
    return vec2(lo, hi);
}

float pxSpanExit(vec2 span, float X0, float dX) {
    if (dX > 0.0f)
        return (span.y - X0) / dX;
    if (dX < 0.0f)
        return (span.x - X0) / dX;
    return PX_BIG;
}

// The cell the ray occupies at parameter t, kept inside a node's span against rounding.
int pxCellInSpan(float X, float dX, vec2 span) {
    return int(clamp(float(pxCellAlong(X, dX)), span.x, span.y - 1.0f));
}

// Where the ray entered `cell` (or started), computed as the cell walk of `exact` computes it:
// solving the cell's quadratic from the same start rounds the same way, so a ray that grazes
// the surface within float rounding gets the reference's answer, not a coin toss of its own.
float pxCellEntry(ivec2 cell, vec2 X0, vec2 dXY) {
    float ex = dXY.x == 0.0f ? 0.0f : pxBorderT(cell.x - (dXY.x > 0.0f ? 1 : -1), X0.x, dXY.x);
    float ey = dXY.y == 0.0f ? 0.0f : pxBorderT(cell.y - (dXY.y > 0.0f ? 1 : -1), X0.y, dXY.y);
    return max(pxStartT(), max(ex, ey));
}

float pxTracePyramid(vec2 uv0, vec2 P) {
    vec2 X0 = pxCellCoords(uv0);
    vec2 dXY = pxCellsPerT(P);
    float t = pxStartT();
    ivec2 cell = pxCellAt(X0, dXY, t);
    // Start at the level whose nodes are about as wide as the whole ray's footprint: any level is
    // correct, and short rays need not descend from the top.
    float span = max(abs(dXY.x), abs(dXY.y)) * (1.0f - t);
    int level = min(pxMaxMipTop, int(ceil(log2(max(span, 1.0f)))));
    for (int i = 0; i < pxMaxSteps; ++i) {
        vec2 spanX = pxNodeSpan(cell.x, level, pxMapSize.x);
        vec2 spanY = pxNodeSpan(cell.y, level, pxMapSize.y);
        float exitX = pxSpanExit(spanX, X0.x, dXY.x);
        float exitY = pxSpanExit(spanY, X0.y, dXY.y);
        float tExit = min(exitX, exitY);
        ivec2 node = ivec2(pxNodeOf(cell.x, level, pxMapSize.x), pxNodeOf(cell.y, level, pxMapSize.y));
        float tTop = max(t, 1.0f - pxMaxMip(level, node));
        if (tTop < tExit) {
            // The ray enters this node's box: through its top if it was above it.
            if (tTop > t) {
                t = tTop;
                cell = ivec2(pxCellInSpan(X0.x + dXY.x * t, dXY.x, spanX),
                             pxCellInSpan(X0.y + dXY.y * t, dXY.y, spanY));
            }
            if (level > 0) {
                level -= 1;
                continue;
            }
            // The box test has shown the ray above the cell before t: no root is lost.
            float ta = min(t, pxCellEntry(cell, X0, dXY));
            float root = pxSolveCell(cell, X0, dXY, ta, min(tExit, 1.0f));
            if (root >= 0.0f)
                return root;
        }
        if (tExit >= 1.0f)
            return 1.0f; // f(1) >= 0: only rounding gets here
        // Step to the neighbouring node: exactly on the axes whose border the ray crosses.
        t = max(t, tExit);
        ivec2 next = ivec2(pxCellInSpan(X0.x + dXY.x * t, dXY.x, spanX),
                           pxCellInSpan(X0.y + dXY.y * t, dXY.y, spanY));
        if (exitX <= exitY)
            next.x = dXY.x > 0.0f ? int(spanX.y) : int(spanX.x) - 1;
        if (exitY <= exitX)
            next.y = dXY.y > 0.0f ? int(spanY.y) : int(spanY.x) - 1;
        // Go up only into a new parent: the old parent's box is already known to be entered.
        ivec2 before = node >> 1;
        ivec2 after = ivec2(pxNodeOf(next.x, level, pxMapSize.x), pxNodeOf(next.y, level, pxMapSize.y)) >> 1;
        cell = next;
        if (before != after)
            level = min(level + 1, pxMaxMipTop);
    }
    return pxFinishExact(X0, dXY, t); // the cap ran out above the surface
}

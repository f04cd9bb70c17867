// A 2-D DDA over the cells the ray crosses for t in [ta, tb], solving each cell's patch exactly.
// Returns (first root, t reached): root is -1 if there is none in [ta, tb] or the budget ran out.

#define PX_SKIP_MARGIN 4.0e-6f
vec2 pxWalkCells(vec2 X0, vec2 dXY, float ta, float tb, int budget) {
    float t = ta;
    ivec2 cell = pxCellAt(X0, dXY, t);
    int stepX = dXY.x > 0.0f ? 1 : -1;
    int stepY = dXY.y > 0.0f ? 1 : -1;
    float nextX = pxBorderT(cell.x, X0.x, dXY.x);
    float nextY = pxBorderT(cell.y, X0.y, dXY.y);
    for (int i = 0; i < budget; ++i) {
        float tEnd = min(min(nextX, nextY), tb);
        // The patch lies below its highest corner: a ray still above it where it leaves the cell
        // has no root there, and skips the quadratic (most cells of a long, grazing ray). The
        // margin covers tEnd's rounding (pxSolvePatch reads up to PX_SPAN_SLACK past it) and the
        // patch read a rounding outside its cell.
        vec4 h = pxCellCorners(cell);
        float top = max(max(h.x, h.y), max(h.z, h.w));
        bool above = (1.0f - tEnd) - tEnd * (2.0f * PX_SPAN_SLACK) > top + PX_SKIP_MARGIN;
        float root = above ? -1.0f : pxSolvePatch(h, cell, X0, dXY, t, tEnd);
        if (root >= 0.0f)
            return vec2(root, root);
        t = max(t, tEnd);
        if (tEnd >= tb)
            return vec2(-1.0f, tb);
        if (nextX <= nextY) {
            cell.x += stepX;
            nextX = pxBorderT(cell.x, X0.x, dXY.x);
        } else {
            cell.y += stepY;
            nextY = pxBorderT(cell.y, X0.y, dXY.y);
        }
    }
    return vec2(-1.0f, t);
}

// The exact finisher of the capped marches (`cone`, `relaxed-cone`, `pyramid`): from a t where
// the ray is known to be above the surface, walk every remaining cell. A march whose step cap
// runs out therefore still ends on the exact hit, paying for the walk only on the rays where the
// cap binds.
float pxFinishExact(vec2 X0, vec2 dXY, float t) {
    vec2 r = pxWalkCells(X0, dXY, t, 1.0f, PX_WALK_LIMIT);
    if (r.x >= 0.0f)
        return r.x;
    return r.y >= 1.0f ? 1.0f : r.y;
}

// The first crossing of a ray known above the surface at tAbove and in the solid at t (a march
// that found itself in the solid after a step): the cells between are walked exactly.
float pxCrossingBefore(vec2 X0, vec2 dXY, float tAbove, float t) {
    if (t <= tAbove)
        return t;
    vec2 r = pxWalkCells(X0, dXY, tAbove, t, PX_WALK_LIMIT);
    return r.x >= 0.0f ? r.x : t; // no root: rounding at the point that found the solid
}

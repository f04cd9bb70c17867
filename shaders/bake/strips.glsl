// Clamp only: beyond the map's edges the surface repeats its edge, flat outward but not along it,
// so a ray can leave the solid there and relaxed cones must see those strips too. Each strip
// beyond an edge segment is bounded by the segment itself, seen as a 0-wide cell: its points are
// nearer, and along the segment the strip falls exactly where the segment does. A 1-D maximum
// pyramid of the segments per side finds the few that matter for an apex.
//
// Sides 0..3: left (x = 0), right (x = W - 1), top (y = 0), bottom (y = H - 1); segment i spans
// texels i .. i + 1 along the side. Bindings:
//   int pxStripLevels(int side)                      0 where the side has no segments
//   int pxStripCount(int side, int level)
//   float pxStripMax(int side, int level, int i)     the segments' highest end, per node

int pxStripSegments(int side) {
    int along = side < 2 ? pxBakeSize.y : pxBakeSize.x;
    int across = side < 2 ? pxBakeSize.x : pxBakeSize.y;
    return pxBakeRepeat || across < 2 ? 0 : along - 1; // a 1-texel side: the cells are the strips
}

// Segment i of a side: its first texel (x, y) in .xy and its extent (0-wide across) in .zw.
ivec4 pxStripSegment(int side, int i) {
    int x = side == 0 ? 0 : (side == 1 ? pxBakeSize.x - 1 : i);
    int y = side == 2 ? 0 : (side == 3 ? pxBakeSize.y - 1 : i);
    return side < 2 ? ivec4(x, y, 0, 1) : ivec4(x, y, 1, 0);
}

#define PX_STRIP_STACK 64
ivec2 pxStripStack[PX_STRIP_STACK]; // (level, index)

// Narrows the relaxed cone c of apex b with every strip segment that may.
float pxStripsNarrow(ivec2 b, float hb, float c) {
    for (int side = 0; side < 4; ++side) {
        int levels = pxStripLevels(side);
        if (levels == 0)
            continue;
        int n = pxStripCount(side, 0);
        int top = 0;
        pxStripStack[0] = ivec2(levels - 1, 0);
        top = 1;
        while (top > 0) {
            top -= 1;
            ivec2 e = pxStripStack[top];
            int level = e.x, index = e.y;
            float m = pxStripMax(side, level, index);
            if (!(m > hb))
                continue;
            int first = index << level;
            int last = min((index + 1) << level, n) - 1;
            ivec4 s = pxStripSegment(side, first);
            ivec2 o = ivec2(s.x - b.x, s.y - b.y);
            int lastX = o.x + (last - first + 1) * s.z;
            int lastY = o.y + (last - first + 1) * s.w;
            PX_PRECISE float d2 = pxBakeDistance2(pxBakeGap(float(o.x), float(lastX)),
                                                  pxBakeGap(float(o.y), float(lastY)));
            PX_PRECISE float rise = m - hb;
            PX_PRECISE float reach2 = c * c * rise * rise * (1.0f + 1.0e-5f);
            if (d2 >= reach2)
                continue;
            if (level == 0) {
                c = min(c, pxBakeRelaxedAt(b, hb, o, ivec2(s.z, s.w), c));
                continue;
            }
            for (int k = 1; k >= 0; --k) {
                if (2 * index + k < pxStripCount(side, level - 1)) {
                    pxStripStack[top] = ivec2(level - 1, 2 * index + k);
                    top += 1;
                }
            }
        }
    }
    return c;
}

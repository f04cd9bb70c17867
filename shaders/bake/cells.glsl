// One cell's bound on a cone (docs/cone-maps.md §1): the cells around the apex exactly, the others
// by a branch and bound on pieces of the cell. Offsets o are texels from the apex b to the cell's
// top-left texel; `span` is the cell's extent (1, or 0 for a 0-wide clamped side or edge strip).
//
// Every value here is a function of the apex and the cell alone, never of the order cells are met
// in or of the cone found so far: a cutoff only drops work whose result could not go below it. So
// any search that meets every cell that can narrow a cone (the ring scan, the pyramid search, the
// GPU's) finds the same cone, to the bit.

// The apex cell seen from b: h = h_b + alpha s + beta t + kappa s t for s, t in [0, 1], as
// (alpha, beta, kappa); the side lengths in uv are pxBakeApexSides().
dvec3 pxBakeApexCell(ivec2 b, double hb, ivec2 o, ivec2 span) {
    int dx = span.x == 0 ? 0 : (o.x == 0 ? 1 : -1);
    int dy = span.y == 0 ? 0 : (o.y == 0 ? 1 : -1);
    double hx = double(pxBakeHeight(ivec2(b.x + dx, b.y)));
    double hy = double(pxBakeHeight(ivec2(b.x, b.y + dy)));
    double hxy = double(pxBakeHeight(ivec2(b.x + dx, b.y + dy)));
    PX_PRECISE double kappa = hxy - hx - hy + hb;
    return dvec3(hx - hb, hy - hb, kappa);
}
dvec2 pxBakeApexSides(ivec2 span) {
    return dvec2(double(span.x) * double(pxBakeInv.x), double(span.y) * double(pxBakeInv.y));
}

// Steepest directional derivative at b into the apex cell (height per uv); -PX_BAKE_FAR for a
// point cell.
double pxBakeSteepestAtApex(dvec3 c, dvec2 ab) {
    if (ab.x > 0 && ab.y > 0) {
        PX_PRECISE double gx = c.x / ab.x;
        PX_PRECISE double gy = c.y / ab.y;
        if (gx >= 0 && gy >= 0) {
            PX_PRECISE double g = sqrt(gx * gx + gy * gy);
            return g;
        }
        return max(gx, gy);
    }
    if (ab.x > 0) {
        PX_PRECISE double g = c.x / ab.x;
        return g;
    }
    if (ab.y > 0) {
        PX_PRECISE double g = c.y / ab.y;
        return g;
    }
    return -double(PX_BAKE_FAR);
}

// max over t in [0, 1] of (p + q t) / sqrt(a^2 + b^2 t^2), a > 0: the secant slope along a far
// edge. Its derivative vanishes only at t = q a^2 / (p b^2).
double pxBakeEdgeSecant(double p, double q, double a, double b) {
    PX_PRECISE double atEnd = (p + q) / sqrt(a * a + b * b);
    PX_PRECISE double best = max(p / a, atEnd);
    if (b > 0 && p != 0) {
        PX_PRECISE double t = q * a * a / (p * b * b);
        if (t > 0 && t < 1) {
            PX_PRECISE double inside = (p + q * t) / sqrt(a * a + b * b * t * t);
            best = max(best, inside);
        }
    }
    return best;
}

// Exact conservative bound over an apex cell: along each ray from b the secant slope of a bilinear
// patch is linear in the distance, so its maximum is the steepest directional derivative at b or
// lies on a far edge. 1 / that slope, or PX_BAKE_FAR if the cell never rises above h_b.
double pxBakeApexConservative(ivec2 b, double hb, ivec2 o, ivec2 span) {
    dvec3 c = pxBakeApexCell(b, hb, o, span);
    dvec2 ab = pxBakeApexSides(span);
    double steepest = pxBakeSteepestAtApex(c, ab);
    if (ab.x > 0)
        steepest = max(steepest, pxBakeEdgeSecant(c.x, c.y + c.z, ab.x, ab.y));
    if (ab.y > 0)
        steepest = max(steepest, pxBakeEdgeSecant(c.y, c.x + c.z, ab.y, ab.x));
    if (!(steepest > 0))
        return double(PX_BAKE_FAR);
    PX_PRECISE double r = 1 / steepest;
    return r;
}

// The radial derivative grad h . (q - b) at the cell's corners (00, 10, 01, 11), from its corner
// heights k, in double: bilinear over the cell, so its corners decide whether any point of the
// cell falls away from b.
dvec4 pxBakeRadial(vec4 k, ivec2 o, ivec2 span) {
    PX_PRECISE double sTop = double(k.y) - double(k.x);
    PX_PRECISE double sBottom = double(k.w) - double(k.z);
    PX_PRECISE double tLeft = double(k.z) - double(k.x);
    PX_PRECISE double tRight = double(k.w) - double(k.y);
    double ox = double(o.x), oy = double(o.y), ex = double(o.x + span.x), ey = double(o.y + span.y);
    PX_PRECISE dvec4 r = dvec4(sTop * ox + tLeft * oy, sTop * ex + tRight * oy,
                               sBottom * ox + tLeft * ey, sBottom * ex + tRight * ey);
    return r;
}

bool pxBakeFallsAway(vec4 k, ivec2 o, ivec2 span) {
    dvec4 r = pxBakeRadial(k, o, span);
    return min(min(r.x, r.y), min(r.z, r.w)) < 0;
}

// Relaxed bound over an apex cell: along a ray from b, h = h_b + A r + K r^2 falls away from b only
// where A + 2 K r < 0, and there the secant is below A / 2: so 2 / (steepest slope at b), or
// PX_BAKE_FAR if the cell cannot fall away anywhere.
double pxBakeApexRelaxed(ivec2 b, double hb, ivec2 o, ivec2 span) {
    if (!pxBakeFallsAway(pxBakeCorners(b + o, span), o, span))
        return double(PX_BAKE_FAR);
    double steepest = pxBakeSteepestAtApex(pxBakeApexCell(b, hb, o, span), pxBakeApexSides(span));
    if (!(steepest > 0))
        return double(PX_BAKE_FAR);
    PX_PRECISE double r = 2 / steepest;
    return r;
}

// Bilinear interpolation of corner values v (00, 10, 01, 11) at (s, t).
double pxBakeLerp2(dvec4 v, double s, double t) {
    PX_PRECISE double r = (v.x * (1 - s) + v.y * s) * (1 - t) + (v.z * (1 - s) + v.w * s) * t;
    return r;
}

// Horizontal uv distance from b to the texel rectangle [x0, x1] x [y0, y1], in double.
double pxBakeDistanceD(double x0, double x1, double y0, double y1) {
    PX_PRECISE double dx = max(double(0), max(x0, -x1)) * (1 / double(pxBakeSize.x));
    PX_PRECISE double dy = max(double(0), max(y0, -y1)) * (1 / double(pxBakeSize.y));
    PX_PRECISE double d = sqrt(dx * dx + dy * dy);
    return d;
}

// Upper bound of the secant slope (h(q) - h_b) / |q - b| over the piece [s0, s1] x [t0, t1] of the
// cell (per uv). The patch is its linearisation L at the piece's centre plus at most
// |K| ds dt / 4; for linear L the secant is (L(b) - h_b) / r plus L's gradient along the direction
// to q, maximised over the directions the piece spans. Unlike max-height over nearest distance this
// stays tight along rays: on a plane the secant is constant along every ray from b.
// vx, vy: the piece's corners in uv relative to b (never at b: the cell has no corner there), len
// their distances, rNear and rFar the nearest and farthest point's.
double pxBakeSecantBound(dvec4 h, ivec2 o, double hb, dvec4 piece, dvec4 vx, dvec4 vy, dvec4 len,
                         double rNear, double rFar) {
    double s0 = piece.x, s1 = piece.y, t0 = piece.z, t1 = piece.w;
    PX_PRECISE double A = h.y - h.x;
    PX_PRECISE double B = h.z - h.x;
    PX_PRECISE double K = h.x - h.y - h.z + h.w;
    PX_PRECISE double sc = (s0 + s1) / 2;
    PX_PRECISE double tc = (t0 + t1) / 2;
    PX_PRECISE double gs = A + K * tc;
    PX_PRECISE double gt = B + K * sc;
    double ox = double(o.x), oy = double(o.y);
    PX_PRECISE double lift = h.x - K * sc * tc - gs * ox - gt * oy - hb +
                             abs(K) * (s1 - s0) * (t1 - t0) / 4;
    // The gradient per uv (a 0-wide side has A = K = 0, so gs = 0).
    PX_PRECISE double gx = gs * double(pxBakeSize.x);
    PX_PRECISE double gy = gt * double(pxBakeSize.y);
    double along = 0;
    PX_PRECISE double gLen = sqrt(gx * gx + gy * gy);
    if (gLen > 0) {
        // A cell lies in one closed quadrant around b, so its corners are within 90 degrees of
        // the direction c to their centre, where the sine of the angle from c orders them.
        PX_PRECISE double cx = vx.x + vx.y + vx.z + vx.w;
        PX_PRECISE double cy = vy.x + vy.y + vy.z + vy.w;
        double lo = double(PX_BAKE_FAR), hi = -double(PX_BAKE_FAR);
        along = -double(PX_BAKE_FAR);
        for (int k = 0; k < 4; ++k) {
            PX_PRECISE double sine = (cx * vy[k] - cy * vx[k]) / len[k];
            PX_PRECISE double dot = (gx * vx[k] + gy * vy[k]) / len[k];
            lo = min(lo, sine);
            hi = max(hi, sine);
            along = max(along, dot);
        }
        PX_PRECISE double sineG = (cx * gy - cy * gx) / gLen;
        PX_PRECISE double toward = cx * gx + cy * gy;
        if (toward > 0 && sineG >= lo && sineG <= hi)
            along = gLen;
    }
    PX_PRECISE double r = along + lift / (lift >= 0 ? rNear : rFar);
    return r;
}

// The branch and bound's limits: pieces are split at most this deep, and at most this many times
// in all (then every remaining piece is accepted as it is; no map of the tests comes near).
#define PX_BAKE_PIECE_DEPTH 24
#define PX_BAKE_PIECE_SPLITS 2048
#define PX_BAKE_PIECE_STACK 104

dvec4 pxBakePieceStack[PX_BAKE_PIECE_STACK];  // (s0, s1, t0, t1)
dvec2 pxBakePieceBounds[PX_BAKE_PIECE_STACK]; // (the parent's lower bound, the best upper bound
                                              //  its ancestors' corners gave)
int pxBakePieceDepth[PX_BAKE_PIECE_STACK];

// Tight lower bound of min |q - b| / (h(q) - h_b) over the cell's points q with h(q) > h_b (and, if
// `fallingOnly`, falling away from b): within a relative `tolerance` below the true minimum. Pieces
// whose bound is at least `cutoff` are dropped; so the result is exact (the same for every cutoff)
// when it is below the cutoff, and at least the cutoff otherwise. For that, each piece's bounds
// come from the piece and its ancestors only: its lower bound is at least its parent's, and it
// stops splitting once that is within the tolerance of the best admissible corner met on the way
// down. PX_BAKE_FAR if no point qualifies.
double pxBakeCellBound(ivec2 b, double hb, ivec2 o, ivec2 span, bool fallingOnly, float cutoff,
                       double tolerance) {
    vec4 k = pxBakeCorners(b + o, span);
    dvec4 h = dvec4(double(k.x), double(k.y), double(k.z), double(k.w));
    dvec4 radial = pxBakeRadial(k, o, span);
    double ox = double(o.x), oy = double(o.y), wx = double(span.x), wy = double(span.y);
    double invW = 1 / double(pxBakeSize.x), invH = 1 / double(pxBakeSize.y);
    int top = 0;
    pxBakePieceStack[0] = dvec4(0, 1, 0, 1);
    pxBakePieceBounds[0] = dvec2(0, double(PX_BAKE_FAR));
    pxBakePieceDepth[0] = 0;
    top = 1;
    double best = double(PX_BAKE_FAR);
    int splits = 0;
    while (top > 0) {
        top -= 1;
        dvec4 p = pxBakePieceStack[top];
        dvec2 inherited = pxBakePieceBounds[top];
        int depth = pxBakePieceDepth[top];
        dvec4 ss = dvec4(p.x, p.y, p.x, p.y);
        dvec4 ts = dvec4(p.z, p.z, p.w, p.w);
        dvec4 hc = dvec4(pxBakeLerp2(h, ss.x, ts.x), pxBakeLerp2(h, ss.y, ts.y),
                         pxBakeLerp2(h, ss.z, ts.z), pxBakeLerp2(h, ss.w, ts.w));
        dvec4 rc = dvec4(pxBakeLerp2(radial, ss.x, ts.x), pxBakeLerp2(radial, ss.y, ts.y),
                         pxBakeLerp2(radial, ss.z, ts.z), pxBakeLerp2(radial, ss.w, ts.w));
        double hMax = max(max(hc.x, hc.y), max(hc.z, hc.w));
        double rMin = min(min(rc.x, rc.y), min(rc.z, rc.w));
        if (hMax <= hb || (fallingOnly && rMin >= 0))
            continue;
        PX_PRECISE double x0 = ox + wx * p.x;
        PX_PRECISE double x1 = ox + wx * p.y;
        PX_PRECISE double y0 = oy + wy * p.z;
        PX_PRECISE double y1 = oy + wy * p.w;
        double rNear = pxBakeDistanceD(x0, x1, y0, y1);
        PX_PRECISE dvec4 vx = dvec4(x0 * invW, x1 * invW, x0 * invW, x1 * invW);
        PX_PRECISE dvec4 vy = dvec4(y0 * invH, y0 * invH, y1 * invH, y1 * invH);
        PX_PRECISE dvec4 len = dvec4(sqrt(vx.x * vx.x + vy.x * vy.x), sqrt(vx.y * vx.y + vy.y * vy.y),
                                     sqrt(vx.z * vx.z + vy.z * vy.z), sqrt(vx.w * vx.w + vy.w * vy.w));
        double rFar = max(max(len.x, len.y), max(len.z, len.w));
        double secant = pxBakeSecantBound(h, o, hb, p, vx, vy, len, rNear, rFar);
        if (secant <= 0)
            continue; // no point of the piece rises above the apex
        PX_PRECISE double byHeight = rNear / (hMax - hb);
        PX_PRECISE double bySecant = 1 / secant;
        double lower = max(max(byHeight, bySecant), inherited.x);
        if (lower >= double(cutoff))
            continue;
        // Corners that are themselves admissible points give an upper bound of the minimum.
        double upper = inherited.y;
        for (int c = 0; c < 4; ++c) {
            if (hc[c] > hb && (!fallingOnly || rc[c] < 0)) {
                PX_PRECISE double ratio = len[c] / (hc[c] - hb);
                upper = min(upper, ratio);
            }
        }
        PX_PRECISE double enough = upper * (1 - tolerance);
        if (lower >= enough || depth >= PX_BAKE_PIECE_DEPTH || splits >= PX_BAKE_PIECE_SPLITS) {
            best = min(best, lower);
            continue;
        }
        splits += 1;
        double sm = span.x > 0 ? (p.x + p.y) / 2 : p.y;
        double tm = span.y > 0 ? (p.z + p.w) / 2 : p.w;
        dvec2 passed = dvec2(lower, upper);
        pxBakePieceStack[top] = dvec4(p.x, sm, p.z, tm);
        pxBakePieceBounds[top] = passed;
        pxBakePieceDepth[top] = depth + 1;
        top += 1;
        if (sm < p.y) {
            pxBakePieceStack[top] = dvec4(sm, p.y, p.z, tm);
            pxBakePieceBounds[top] = passed;
            pxBakePieceDepth[top] = depth + 1;
            top += 1;
        }
        if (tm < p.w) {
            pxBakePieceStack[top] = dvec4(p.x, sm, tm, p.w);
            pxBakePieceBounds[top] = passed;
            pxBakePieceDepth[top] = depth + 1;
            top += 1;
        }
        if (sm < p.y && tm < p.w) {
            pxBakePieceStack[top] = dvec4(sm, p.y, tm, p.w);
            pxBakePieceBounds[top] = passed;
            pxBakePieceDepth[top] = depth + 1;
            top += 1;
        }
    }
    return best;
}

// The bakers' tolerances: the oracle's (as tight as the definition allows, for tests) and the
// relaxed bakers' (a 3% narrower cone at worst, for a bake several times faster).
#define PX_BAKE_ORACLE_TOLERANCE 1.0e-3f
#define PX_BAKE_RELAXED_TOLERANCE 3.0e-2f

// The relaxed bound of the cell at offset o with corners k, for an apex that is not one of its
// corners: PX_BAKE_FAR where no point of it rises above h_b and falls away from b, else within
// the tolerance below the exact bound. Exact (independent of the cutoff) wherever it is below
// `cutoff`; the cheap rejections first, the branch and bound only where the cell may go below it.
float pxBakeRelaxedCell(ivec2 b, float hb, ivec2 o, ivec2 span, vec4 k, float cutoff) {
    float rise = pxBakeMax4(k) - hb;
    if (!(rise > 0.0f))
        return PX_BAKE_FAR;
    PX_PRECISE float plain = pxBakeDistance(pxBakeGap(float(o.x), float(o.x + span.x)),
                                            pxBakeGap(float(o.y), float(o.y + span.y))) / rise;
    if (plain >= cutoff || !pxBakeFallsAway(k, o, span))
        return PX_BAKE_FAR;
    double bound = pxBakeCellBound(b, double(hb), o, span, true, cutoff,
                                   double(PX_BAKE_RELAXED_TOLERANCE));
    return max(plain, pxBakeFloatDown(bound));
}

// The same for any cell, the apex's own included.
float pxBakeRelaxedAt(ivec2 b, float hb, ivec2 o, ivec2 span, float cutoff) {
    if (pxBakeIsApexCell(o, span))
        return pxBakeFloatDown(pxBakeApexRelaxed(b, double(hb), o, span));
    return pxBakeRelaxedCell(b, hb, o, span, pxBakeCorners(b + o, span), cutoff);
}

// A conservative cell bound as the brute-force oracle computes it: exact around the apex, else
// the plain bound (distance to the cell over its height above the apex) where that cannot go below
// the cutoff, else the branch and bound within the oracle's tolerance.
float pxBakeConservativeAt(ivec2 b, float hb, ivec2 o, float cutoff) {
    ivec2 span = pxBakeSpan();
    if (pxBakeIsApexCell(o, span))
        return pxBakeFloatDown(pxBakeApexConservative(b, double(hb), o, span));
    float rise = pxBakeMax4(pxBakeCorners(b + o, span)) - hb;
    if (!(rise > 0.0f))
        return PX_BAKE_FAR;
    PX_PRECISE float plain = pxBakeDistance(pxBakeGap(float(o.x), float(o.x + span.x)),
                                            pxBakeGap(float(o.y), float(o.y + span.y))) / rise;
    if (plain >= cutoff)
        return PX_BAKE_FAR;
    double bound = pxBakeCellBound(b, double(hb), o, span, false, cutoff,
                                   double(PX_BAKE_ORACLE_TOLERANCE));
    return max(plain, pxBakeFloatDown(bound));
}

#include "bake/ConeCells.h"

#include <array>
#include <limits>

namespace px::cone {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The apex cell seen from b: heights at b, at the neighbour along x and y, and diagonally, with
// the cell's side lengths in uv (0 for a 0-wide clamped side).
struct ApexCell {
    double alpha, beta, kappa; // h = h_b + alpha s + beta t + kappa s t, s, t in [0, 1]
    double a, b;               // uv length of the cell's x and y sides
};

ApexCell apexCell(const CellGrid& g, const Apex& apex, int ox, int oy, Shape shape) {
    const int wx = shape.wx, wy = shape.wy;
    const int dx = wx == 0 ? 0 : (ox == 0 ? 1 : -1);
    const int dy = wy == 0 ? 0 : (oy == 0 ? 1 : -1);
    const double hb = apex.h;
    const double hx = g.texel(apex.x + dx, apex.y), hy = g.texel(apex.x, apex.y + dy);
    const double hxy = g.texel(apex.x + dx, apex.y + dy);
    return {hx - hb, hy - hb, hxy - hx - hy + hb, wx * static_cast<double>(g.invW),
            wy * static_cast<double>(g.invH)};
}

// Steepest directional derivative at b into the cell (height per uv), -inf for a point cell.
double steepestAtApex(const ApexCell& c) {
    if (c.a > 0 && c.b > 0) {
        const double gx = c.alpha / c.a, gy = c.beta / c.b;
        return gx >= 0 && gy >= 0 ? std::sqrt(gx * gx + gy * gy) : std::max(gx, gy);
    }
    if (c.a > 0)
        return c.alpha / c.a;
    if (c.b > 0)
        return c.beta / c.b;
    return -kInf;
}

// max over t in [0, 1] of (p + q t) / sqrt(a^2 + b^2 t^2), a > 0: the secant slope along a far
// edge. Its derivative vanishes only at t = q a^2 / (p b^2).
double edgeSecant(double p, double q, double a, double b) {
    double best = std::max(p / a, (p + q) / std::sqrt(a * a + b * b));
    if (b > 0 && p != 0) {
        const double t = q * a * a / (p * b * b);
        if (t > 0 && t < 1)
            best = std::max(best, (p + q * t) / std::sqrt(a * a + b * b * t * t));
    }
    return best;
}

} // namespace

double apexConservativeBound(const CellGrid& g, const Apex& b, int ox, int oy, Shape shape) {
    const ApexCell c = apexCell(g, b, ox, oy, shape);
    double steepest = steepestAtApex(c);
    if (c.a > 0)
        steepest = std::max(steepest, edgeSecant(c.alpha, c.beta + c.kappa, c.a, c.b));
    if (c.b > 0)
        steepest = std::max(steepest, edgeSecant(c.beta, c.alpha + c.kappa, c.b, c.a));
    return steepest > 0 ? 1.0 / steepest : kInf;
}

double apexRelaxedBound(const CellGrid& g, const Apex& b, int ox, int oy, Shape shape) {
    if (!cellFallsAway(g, b, ox, oy, shape))
        return kInf;
    const double steepest = steepestAtApex(apexCell(g, b, ox, oy, shape));
    return steepest > 0 ? 2.0 / steepest : kInf;
}

namespace {

// A cell relative to b in double precision: corner heights, the radial derivative
// grad h . (q - b) at the corners (bilinear in the cell, like h), and its texel-unit extent.
struct CellFrame {
    std::array<double, 4> h; // 00, 10, 01, 11
    std::array<double, 4> radial;
    double ox, oy, wx, wy;
    double invW, invH;

    double distance(double x0, double x1, double y0, double y1) const {
        const double dx = std::max(0.0, std::max(x0, -x1)) * invW;
        const double dy = std::max(0.0, std::max(y0, -y1)) * invH;
        return std::sqrt(dx * dx + dy * dy);
    }
    static double lerp2(const std::array<double, 4>& v, double s, double t) {
        return (v[0] * (1 - s) + v[1] * s) * (1 - t) + (v[2] * (1 - s) + v[3] * s) * t;
    }
};

CellFrame cellFrame(const CellGrid& g, const Apex& b, int ox, int oy, Shape shape) {
    const int wx = shape.wx, wy = shape.wy;
    const int x = b.x + ox, y = b.y + oy;
    CellFrame f;
    f.h = {g.texel(x, y), g.texel(x + wx, y), g.texel(x, y + wy), g.texel(x + wx, y + wy)};
    // d h / d s along the top and bottom edges, d h / d t along the left and right edges.
    const double sTop = f.h[1] - f.h[0], sBottom = f.h[3] - f.h[2];
    const double tLeft = f.h[2] - f.h[0], tRight = f.h[3] - f.h[1];
    f.radial = {sTop * ox + tLeft * oy, sTop * (ox + wx) + tRight * oy,
                sBottom * ox + tLeft * (oy + wy), sBottom * (ox + wx) + tRight * (oy + wy)};
    f.ox = ox;
    f.oy = oy;
    f.wx = wx;
    f.wy = wy;
    f.invW = 1.0 / g.field->width;
    f.invH = 1.0 / g.field->height;
    return f;
}

// Upper bound of the secant slope (h(q) - h_b) / |q - b| over the piece [s0,s1] x [t0,t1] of the
// cell (per uv). The patch is its linearisation L at the piece's centre plus at most
// |K| ds dt / 4; for linear L the secant is (L(b) - h_b) / r plus L's gradient along the
// direction to q, maximised over the directions the piece spans. Unlike max-height over nearest
// distance this stays tight along rays: on a plane the secant is constant along every ray from
// b, and the plain bound would need the whole ray cut into tiny pieces.
double secantBound(const CellFrame& f, double hb, double s0, double s1, double t0, double t1,
                   double rNear) {
    const double A = f.h[1] - f.h[0], B = f.h[2] - f.h[0], K = f.h[0] - f.h[1] - f.h[2] + f.h[3];
    const double sc = 0.5 * (s0 + s1), tc = 0.5 * (t0 + t1);
    const double gs = A + K * tc, gt = B + K * sc; // dh/ds, dh/dt at the centre
    // L in texel units relative to b: s = x - ox (a 0-wide side has A = K = 0, so gs = 0).
    const double lift = f.h[0] - K * sc * tc - gs * f.ox - gt * f.oy - hb +
                        std::abs(K) * (s1 - s0) * (t1 - t0) * 0.25;
    const double gx = gs / f.invW, gy = gt / f.invH; // gradient per uv
    // Corners of the piece in uv, relative to b (never at b: the cell has no corner there).
    double vx[4], vy[4], rFar = 0;
    for (int k = 0; k < 4; ++k) {
        vx[k] = (f.ox + f.wx * (k & 1 ? s1 : s0)) * f.invW;
        vy[k] = (f.oy + f.wy * (k & 2 ? t1 : t0)) * f.invH;
        rFar = std::max(rFar, std::sqrt(vx[k] * vx[k] + vy[k] * vy[k]));
    }
    double along = 0;
    const double gLen = std::sqrt(gx * gx + gy * gy);
    if (gLen > 0) {
        // A cell lies in one closed quadrant around b, so its corners are within 90 degrees of
        // the direction c to their centre, where the sine of the angle from c orders them.
        const double cx = vx[0] + vx[1] + vx[2] + vx[3], cy = vy[0] + vy[1] + vy[2] + vy[3];
        double lo = kInf, hi = -kInf;
        along = -kInf;
        for (int k = 0; k < 4; ++k) {
            const double len = std::sqrt(vx[k] * vx[k] + vy[k] * vy[k]);
            const double sine = (cx * vy[k] - cy * vx[k]) / len;
            lo = std::min(lo, sine);
            hi = std::max(hi, sine);
            along = std::max(along, (gx * vx[k] + gy * vy[k]) / len);
        }
        const double sineG = (cx * gy - cy * gx) / gLen;
        if (cx * gx + cy * gy > 0 && sineG >= lo && sineG <= hi)
            along = gLen;
    }
    return along + lift / (lift >= 0 ? rNear : rFar);
}

} // namespace

bool cellFallsAway(const CellGrid& g, const Apex& b, int ox, int oy, Shape shape) {
    const int x = b.x + ox, y = b.y + oy;
    const Corners k{g.texel(x, y), g.texel(x + shape.wx, y), g.texel(x, y + shape.wy),
                    g.texel(x + shape.wx, y + shape.wy)};
    return cornersFallAway(k, ox, oy, shape);
}

double cellBound(const CellGrid& g, const Apex& apex, int ox, int oy, Shape shape, bool fallingOnly,
                 float cutoff, double tolerance) {
    constexpr int kMaxDepth = 24;
    constexpr int kMaxSplits = 2048; // then every remaining piece is accepted as it is
    const CellFrame f = cellFrame(g, apex, ox, oy, shape);
    const double hb = apex.h;

    struct Piece {
        double s0, s1, t0, t1;
        int depth;
    };
    std::array<Piece, 4 * kMaxDepth + 8> stack;
    int top = 0;
    stack[top++] = {0, 1, 0, 1, 0};
    double best = kInf, upper = kInf;
    int splits = 0;
    while (top > 0) {
        const Piece p = stack[--top];
        const double ss[4] = {p.s0, p.s1, p.s0, p.s1}, ts[4] = {p.t0, p.t0, p.t1, p.t1};
        double h[4], r[4];
        double hMax = -kInf, rMin = kInf;
        for (int k = 0; k < 4; ++k) {
            h[k] = CellFrame::lerp2(f.h, ss[k], ts[k]);
            r[k] = CellFrame::lerp2(f.radial, ss[k], ts[k]);
            hMax = std::max(hMax, h[k]);
            rMin = std::min(rMin, r[k]);
        }
        if (hMax <= hb || (fallingOnly && rMin >= 0))
            continue;
        const double x0 = f.ox + f.wx * p.s0, x1 = f.ox + f.wx * p.s1;
        const double y0 = f.oy + f.wy * p.t0, y1 = f.oy + f.wy * p.t1;
        const double rNear = f.distance(x0, x1, y0, y1);
        const double secant = secantBound(f, hb, p.s0, p.s1, p.t0, p.t1, rNear);
        if (secant <= 0)
            continue; // no point of the piece rises above the apex
        const double lower = std::max(rNear / (hMax - hb), 1.0 / secant);
        if (lower >= cutoff)
            continue;
        // Corners that are themselves admissible points give an upper bound of the minimum.
        for (int k = 0; k < 4; ++k) {
            if (h[k] > hb && (!fallingOnly || r[k] < 0)) {
                const double x = f.ox + f.wx * ss[k], y = f.oy + f.wy * ts[k];
                upper = std::min(upper, f.distance(x, x, y, y) / (h[k] - hb));
            }
        }
        if (lower >= upper * (1 - tolerance) || p.depth >= kMaxDepth || splits >= kMaxSplits) {
            best = std::min(best, lower);
            continue;
        }
        ++splits;
        const double sm = f.wx > 0 ? 0.5 * (p.s0 + p.s1) : p.s1;
        const double tm = f.wy > 0 ? 0.5 * (p.t0 + p.t1) : p.t1;
        const int d = p.depth + 1;
        stack[top++] = {p.s0, sm, p.t0, tm, d};
        if (sm < p.s1)
            stack[top++] = {sm, p.s1, p.t0, tm, d};
        if (tm < p.t1)
            stack[top++] = {p.s0, sm, tm, p.t1, d};
        if (sm < p.s1 && tm < p.t1)
            stack[top++] = {sm, p.s1, tm, p.t1, d};
    }
    return best;
}

} // namespace px::cone

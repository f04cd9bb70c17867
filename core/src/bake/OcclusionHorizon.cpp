#include "bake/OcclusionHorizon.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace px::occlusion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

int floorDiv(int a, int b) {
    return a >= 0 ? a / b : -((-a - 1) / b) - 1;
}

// The cell a ray from lattice point p enters first along one axis (d: its direction there): the
// one ahead of p, or for a ray along the grid line either neighbour inside the map.
int firstCell(int p, double d, int cells, bool clamp) {
    if (d > 0.0)
        return p;
    if (d < 0.0)
        return p - 1;
    return clamp && p >= cells && p > 0 ? p - 1 : p;
}

// The cell a ray moving d per uv is in at coordinate t (a cell line itself: the one ahead);
// `current` if it does not move along this axis. (No floor(): a library call without SSE4.1.)
int cellAhead(double t, double d, int current) {
    if (d == 0.0)
        return current;
    int i = static_cast<int>(t);
    if (static_cast<double>(i) > t)
        --i; // i = floor(t)
    return d > 0.0 || static_cast<double>(i) != t ? i : i - 1;
}

} // namespace

HorizonSearch::HorizonSearch(const HeightField& field, WrapMode wrap, double heightScale,
                             double distance)
    : m_field(field), m_wrap(wrap), m_scale(heightScale), m_distance(distance),
      m_top(heightScale * static_cast<double>(field.maxHeight())),
      m_cellsX(wrap == WrapMode::Repeat ? field.width : field.width - 1),
      m_cellsY(wrap == WrapMode::Repeat ? field.height : field.height - 1) {
    if (m_cellsX <= 0 || m_cellsY <= 0)
        return; // a clamped map one texel wide or high: no cells inside, only the edge profile
    // Level 1: the highest corner of each 2 x 2 cells; then 2 x 2 nodes, sizes rounded up.
    Level first;
    first.width = (m_cellsX + 1) / 2;
    first.height = (m_cellsY + 1) / 2;
    first.max.resize(static_cast<std::size_t>(first.width) * first.height);
    for (int ny = 0; ny < first.height; ++ny) {
        for (int nx = 0; nx < first.width; ++nx) {
            float m = -std::numeric_limits<float>::infinity();
            const int x1 = std::min(2 * nx + 2, m_cellsX), y1 = std::min(2 * ny + 2, m_cellsY);
            for (int y = 2 * ny; y <= y1; ++y) {
                for (int x = 2 * nx; x <= x1; ++x)
                    m = std::max(m, texel(x, y));
            }
            first.max[static_cast<std::size_t>(ny) * first.width + nx] = m;
        }
    }
    m_levels.push_back(std::move(first));
    while (m_levels.back().width > 1 || m_levels.back().height > 1) {
        const Level& below = m_levels.back();
        Level up;
        up.width = (below.width + 1) / 2;
        up.height = (below.height + 1) / 2;
        up.max.resize(static_cast<std::size_t>(up.width) * up.height);
        for (int ny = 0; ny < up.height; ++ny) {
            for (int nx = 0; nx < up.width; ++nx) {
                float m = -std::numeric_limits<float>::infinity();
                for (int y = 2 * ny; y < std::min(2 * ny + 2, below.height); ++y) {
                    for (int x = 2 * nx; x < std::min(2 * nx + 2, below.width); ++x)
                        m = std::max(m, below.max[static_cast<std::size_t>(y) * below.width + x]);
                }
                up.max[static_cast<std::size_t>(ny) * up.width + nx] = m;
            }
        }
        m_levels.push_back(std::move(up));
    }
}

float HorizonSearch::texel(int x, int y) const {
    return m_field.at(wrapIndex(x, m_field.width, m_wrap), wrapIndex(y, m_field.height, m_wrap));
}

float HorizonSearch::nodeMax(int level, int nx, int ny) const {
    const Level& l = m_levels[static_cast<std::size_t>(level - 1)];
    return l.max[static_cast<std::size_t>(ny) * l.width + nx];
}

double HorizonSearch::surface(double x, double y) const {
    const double fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    const double tx = x - fx, ty = y - fy;
    const double top = texel(ix, iy) * (1.0 - tx) + texel(ix + 1, iy) * tx;
    const double bottom = texel(ix, iy + 1) * (1.0 - tx) + texel(ix + 1, iy + 1) * tx;
    return top * (1.0 - ty) + bottom * ty;
}

double HorizonSearch::cellSecant(int lx, int ly, double ax, double ay, double zp, double dx,
                                 double dy, double ra, double rb, double best, double& at) const {
    // Corners by local cell coordinates: with repeat the last cell's far side wraps to 0.
    const int W = m_field.width, H = m_field.height;
    const int lx1 = lx + 1 < W ? lx + 1 : 0, ly1 = ly + 1 < H ? ly + 1 : 0;
    const float* row0 = &m_field.texels[static_cast<std::size_t>(ly) * W];
    const float* row1 = &m_field.texels[static_cast<std::size_t>(ly1) * W];
    const double h00 = row0[lx], h10 = row0[lx1], h01 = row1[lx], h11 = row1[lx1];
    const double e1 = h10 - h00, e2 = h01 - h00, k = h11 - h10 - h01 + h00;
    // (ax, ay): p in the cell's own coordinates. Along the ray inside the cell
    // z(r) - z(p) = A + B r + C r^2.
    const auto consider = [&](double r) {
        const double fx = std::clamp(ax + dx * r, 0.0, 1.0);
        const double fy = std::clamp(ay + dy * r, 0.0, 1.0);
        const double g = m_scale * (h00 + e1 * fx + e2 * fy + k * fx * fy) - zp;
        if (g > best * r) {
            best = g / r;
            at = r;
        }
    };
    // The entry point was the previous cell's exit, or lies in a node shown not to rise enough.
    consider(rb);
    if (ra <= 0.0) {
        // The r -> 0+ limit: the surface is z(p) + B r + C r^2 there.
        const double B = m_scale * (e1 * dx + e2 * dy + k * (ax * dy + ay * dx));
        if (B > best) {
            best = B;
            at = 0.0;
        }
        return best;
    }
    // (A + B r + C r^2) / r has an interior maximum only where A and C are both negative.
    const double C = m_scale * k * dx * dy;
    if (C < 0.0) {
        const double A = m_scale * (h00 + e1 * ax + e2 * ay + k * ax * ay) - zp;
        if (A < 0.0) {
            const double r = std::sqrt(A / C);
            if (r > ra && r < rb)
                consider(r);
        }
    }
    return best;
}

// Clamp, from distance r where the ray has left the cells inside the map: the edge texels extend
// outward, so where the ray is beyond the map along one axis the height follows the edge's profile
// along the other (linear between texels: only the crossings of texel lines matter), and beyond
// along both it is constant.
double HorizonSearch::clampedOutside(int px, int py, double zp, double dx, double dy, double r,
                                     double best, double rMax, bool beyondX, bool beyondY) const {
    const int W = m_field.width, H = m_field.height;
    const double slack = std::isinf(m_distance) ? kOpenSkySlack : 0.0;
    const auto constant = [&](double c, double from) {
        const double g = m_scale * c - zp;
        if (g > 0.0)
            return from > 0.0 ? std::max(best, g / from) : best;
        return std::isinf(rMax) ? std::max(best, 0.0) : std::max(best, g / rMax);
    };
    const int ex = dx > 0.0 ? W - 1 : 0, ey = dy > 0.0 ? H - 1 : 0;
    if ((beyondX && (beyondY || dy == 0.0)) || (beyondY && dx == 0.0)) {
        const int cx = beyondX ? ex : px, cy = beyondY ? ey : py;
        return constant(texel(cx, cy), r);
    }
    // Walk the texel lines across the other axis: t is the coordinate along it.
    const bool alongY = beyondX;
    const double p = alongY ? py : px, d = alongY ? dy : dx;
    const int n = alongY ? H : W;
    const int edge = alongY ? ex : ey;
    const double step = d > 0.0 ? 1.0 : -1.0;
    const double t = p + d * r;
    double line = d > 0.0 ? std::floor(t) + 1.0 : std::ceil(t) - 1.0;
    const auto profile = [&](int i) { return alongY ? texel(edge, i) : texel(i, edge); };
    while (line >= 0.0 && line <= n - 1) {
        const double rLine = std::max((line - p) / d, r);
        const int i = static_cast<int>(line);
        if (rLine >= rMax) {
            const double f = ((p + d * rMax) - (line - step)) * step; // from the previous line
            const double h0 = profile(i - static_cast<int>(step)), h1 = profile(i);
            return std::max(best, (m_scale * (h0 + (h1 - h0) * f) - zp) / rMax);
        }
        best = std::max(best, (m_scale * profile(i) - zp) / rLine);
        if ((m_top - zp) / rLine <= best + slack)
            return best;
        r = rLine;
        line += step;
    }
    return constant(profile(d > 0.0 ? n - 1 : 0), r);
}

double HorizonSearch::horizon(int px, int py, double cosPhi, double sinPhi, double* witness) const {
    const int W = m_field.width, H = m_field.height;
    const bool repeat = m_wrap == WrapMode::Repeat;
    const double dx = W * cosPhi, dy = -H * sinPhi; // texels per uv along the ray
    const double invDx = 1.0 / dx, invDy = 1.0 / dy;
    const double zp = m_scale * m_field.at(px, py);
    const bool open = std::isinf(m_distance);
    const double rMax = open ? (repeat ? kOpenSkyReach : kInf) : m_distance;
    const double slack = open ? kOpenSkySlack : 0.0;
    const double room = m_top - zp; // the most anything can rise above p
    double best = open ? 0.0 : -kInf;
    double at = 0.0;
    if (witness && *witness > 0.0 && *witness <= rMax) {
        const double r = *witness;
        const double g = m_scale * surface(px + dx * r, py + dy * r) - zp;
        if (g > best * r) {
            best = g / r;
            at = r;
        }
    }
    const auto found = [&](double tangent) {
        if (witness)
            *witness = at;
        return tangent;
    };

    // The cell (cx, cy) in extended coordinates, and the first cell of its period (baseX, baseY).
    int cx = firstCell(px, dx, m_cellsX, !repeat);
    int cy = firstCell(py, dy, m_cellsY, !repeat);
    int baseX = repeat ? floorDiv(cx, m_cellsX) * m_cellsX : 0;
    int baseY = repeat ? floorDiv(cy, m_cellsY) * m_cellsY : 0;
    const int top = static_cast<int>(m_levels.size());
    int level = 0;
    double r = 0.0;
    for (;;) {
        if (r > 0.0 && (r >= rMax || room <= (best + slack) * r))
            return found(best);
        if (!repeat && (cx < 0 || cx >= m_cellsX || cy < 0 || cy >= m_cellsY))
            return found(clampedOutside(px, py, zp, dx, dy, r, best, rMax, cx < 0 || cx >= m_cellsX,
                                        cy < 0 || cy >= m_cellsY));
        if (cx - baseX >= m_cellsX)
            baseX += m_cellsX;
        else if (cx < baseX)
            baseX -= m_cellsX;
        if (cy - baseY >= m_cellsY)
            baseY += m_cellsY;
        else if (cy < baseY)
            baseY -= m_cellsY;
        const int lx = cx - baseX, ly = cy - baseY;
        // The node of `level` holding the cell, in extended coordinates.
        const int nx = lx >> level, ny = ly >> level;
        const int x0 = baseX + (nx << level), x1 = baseX + std::min((nx + 1) << level, m_cellsX);
        const int y0 = baseY + (ny << level), y1 = baseY + std::min((ny + 1) << level, m_cellsY);
        const double exitX = dx > 0.0 ? (x1 - px) * invDx : (dx < 0.0 ? (x0 - px) * invDx : kInf);
        const double exitY = dy > 0.0 ? (y1 - py) * invDy : (dy < 0.0 ? (y0 - py) * invDy : kInf);
        const double exit = std::min(exitX, exitY);
        if (level > 0) {
            // Skip the node if no point of it can raise the horizon: its secant is at most
            // (max - z(p)) / r at the nearest r where that is positive, at the farthest otherwise.
            const double rise = m_scale * nodeMax(level, nx, ny) - zp;
            const bool skip = rise > 0.0 ? rise <= (best + slack) * r
                                         : rise <= (best + slack) * std::min(exit, rMax);
            if (!skip) {
                --level;
                continue;
            }
            level = std::min(level + 1, top);
        } else {
            best =
                cellSecant(lx, ly, px - cx, py - cy, zp, dx, dy, r, std::min(exit, rMax), best, at);
        }
        if (exit >= rMax)
            return found(best);
        // Step into the next cell: across the side it leaves by, and along the other to the cell
        // the exit point is in (kept inside the node so that rounding never steps back).
        const double ex = px + dx * exit, ey = py + dy * exit;
        const int nextX = exitX <= exitY ? (dx > 0.0 ? x1 : x0 - 1)
                                         : std::clamp(cellAhead(ex, dx, cx), x0, x1 - 1);
        const int nextY = exitY <= exitX ? (dy > 0.0 ? y1 : y0 - 1)
                                         : std::clamp(cellAhead(ey, dy, cy), y0, y1 - 1);
        // After a cell, look at the level above only once the ray enters a new one of its nodes.
        if (level == 0 && top > 0 &&
            ((nextX - baseX) >> 1 != lx >> 1 || (nextY - baseY) >> 1 != ly >> 1))
            level = 1;
        cx = nextX;
        cy = nextY;
        r = exit;
    }
}

} // namespace px::occlusion

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

double HorizonSearch::cellSecant(int cx, int cy, int px, int py, double zp, double dx, double dy,
                                 double ra, double rb) const {
    const double h00 = texel(cx, cy), h10 = texel(cx + 1, cy);
    const double h01 = texel(cx, cy + 1), h11 = texel(cx + 1, cy + 1);
    const double e1 = h10 - h00, e2 = h01 - h00, k = h11 - h10 - h01 + h00;
    const double ax = px - cx, ay = py - cy; // p in the cell's own coordinates
    // z(r) - z(p) = A + B r + C r^2 along the ray inside the cell.
    const double B = m_scale * (e1 * dx + e2 * dy + k * (ax * dy + ay * dx));
    const double C = m_scale * k * dx * dy;
    const auto secantAt = [&](double r) {
        const double fx = std::clamp(ax + dx * r, 0.0, 1.0);
        const double fy = std::clamp(ay + dy * r, 0.0, 1.0);
        const double h = h00 + e1 * fx + e2 * fy + k * fx * fy;
        return (m_scale * h - zp) / r;
    };
    double best = secantAt(rb);
    if (ra <= 0.0)
        return std::max(best, B); // the r -> 0+ limit: z(p) + B r + C r^2 is the surface there
    best = std::max(best, secantAt(ra));
    // (A + B r + C r^2) / r has an interior maximum only where A and C are both negative.
    const double A = m_scale * (h00 + e1 * ax + e2 * ay + k * ax * ay) - zp;
    if (A < 0.0 && C < 0.0) {
        const double r = std::sqrt(A / C);
        if (r > ra && r < rb)
            best = std::max(best, secantAt(r));
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

double HorizonSearch::horizon(int px, int py, double cosPhi, double sinPhi) const {
    const int W = m_field.width, H = m_field.height;
    const bool repeat = m_wrap == WrapMode::Repeat;
    const double dx = W * cosPhi, dy = -H * sinPhi; // texels per uv along the ray
    const double zp = m_scale * m_field.at(px, py);
    const bool open = std::isinf(m_distance);
    const double rMax = open ? (repeat ? kOpenSkyReach : kInf) : m_distance;
    const double slack = open ? kOpenSkySlack : 0.0;
    double best = open ? 0.0 : -kInf;

    int cx = firstCell(px, dx, m_cellsX, !repeat);
    int cy = firstCell(py, dy, m_cellsY, !repeat);
    const int top = static_cast<int>(m_levels.size());
    int level = 0;
    double r = 0.0;
    for (;;) {
        if (r > 0.0 && (r >= rMax || (m_top - zp) / r <= best + slack))
            return best;
        if (!repeat && (cx < 0 || cx >= m_cellsX || cy < 0 || cy >= m_cellsY))
            return clampedOutside(px, py, zp, dx, dy, r, best, rMax, cx < 0 || cx >= m_cellsX,
                                  cy < 0 || cy >= m_cellsY);
        // The node of `level` holding cell (cx, cy), in extended coordinates.
        const int periodX = repeat ? floorDiv(cx, m_cellsX) : 0;
        const int periodY = repeat ? floorDiv(cy, m_cellsY) : 0;
        const int nx = (cx - periodX * m_cellsX) >> level, ny = (cy - periodY * m_cellsY) >> level;
        const int x0 = periodX * m_cellsX + (nx << level);
        const int x1 = periodX * m_cellsX + std::min((nx + 1) << level, m_cellsX);
        const int y0 = periodY * m_cellsY + (ny << level);
        const int y1 = periodY * m_cellsY + std::min((ny + 1) << level, m_cellsY);
        const double exitX = dx > 0.0 ? (x1 - px) / dx : (dx < 0.0 ? (x0 - px) / dx : kInf);
        const double exitY = dy > 0.0 ? (y1 - py) / dy : (dy < 0.0 ? (y0 - py) / dy : kInf);
        const double exit = std::min(exitX, exitY);
        if (level > 0) {
            // Skip the node if no point of it can raise the horizon: its secant is at most
            // (max - z(p)) / r at the nearest r where that is positive, at the farthest otherwise.
            const double rise = m_scale * nodeMax(level, nx, ny) - zp;
            const bool skip = rise > 0.0 ? rise <= (best + slack) * r
                                         : rise / std::min(exit, rMax) <= best + slack;
            if (!skip) {
                --level;
                continue;
            }
            level = std::min(level + 1, top);
        } else {
            best = std::max(best, cellSecant(cx, cy, px, py, zp, dx, dy, r, std::min(exit, rMax)));
            level = std::min(1, top);
        }
        if (exit >= rMax)
            return best;
        // Step into the next cell: across the side it leaves by, and along the other to the cell
        // the exit point is in (kept inside the node so that rounding never steps back).
        const double ex = px + dx * exit, ey = py + dy * exit;
        const int nextX = exitX <= exitY
                              ? (dx > 0.0 ? x1 : x0 - 1)
                              : std::clamp(dx > 0.0   ? static_cast<int>(std::floor(ex))
                                           : dx < 0.0 ? static_cast<int>(std::ceil(ex)) - 1
                                                      : cx,
                                           x0, x1 - 1);
        const int nextY = exitY <= exitX
                              ? (dy > 0.0 ? y1 : y0 - 1)
                              : std::clamp(dy > 0.0   ? static_cast<int>(std::floor(ey))
                                           : dy < 0.0 ? static_cast<int>(std::ceil(ey)) - 1
                                                      : cy,
                                           y0, y1 - 1);
        cx = nextX;
        cy = nextY;
        r = exit;
    }
}

} // namespace px::occlusion

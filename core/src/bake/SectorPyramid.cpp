#include "bake/SectorPyramid.h"

#include <array>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px::cone {

namespace {

// The sectors' edge directions in uv (edge k starts sector k), counterclockwise from +u.
constexpr int kEdges[kSectors][2] = {{1, 0},  {2, 1},  {1, 1},  {1, 2},   {0, 1},   {-1, 2},
                                     {-1, 1}, {-2, 1}, {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2},
                                     {0, -1}, {1, -2}, {1, -1}, {2, -1}};

// The sectors along which a cell whose gradient (per uv) lies in the box [gx0, gx1] x [gy0, gy1]
// can fall: g . e < 0 for some g of the box and e of the sector, and g . e is smallest at an
// edge direction e and at a corner of the box.
Sectors fallingSectors(double gx0, double gx1, double gy0, double gy1) {
    unsigned edges = 0; // bit k: the surface falls along edge k somewhere in the cell
    for (int k = 0; k < kSectors; ++k) {
        const int ex = kEdges[k][0], ey = kEdges[k][1];
        if ((ex < 0 ? gx1 : gx0) * ex + (ey < 0 ? gy1 : gy0) * ey < 0)
            edges |= 1u << k;
    }
    // Sector k is bounded by edges k and k + 1.
    return static_cast<Sectors>(edges | edges >> 1 | edges << (kSectors - 1));
}

} // namespace

SectorPyramid::SectorPyramid(const CellGrid& g, float heightMax, BakeProgress* progress)
    : m_scale(heightMax > 0.0f ? heightMax / 65535.0f : 0.0f) {
    m_width.push_back(g.cellsX);
    m_height.push_back(g.cellsY);
    m_flags.resize(static_cast<std::size_t>(g.cellsX) * g.cellsY);
    const double W = g.field->width, H = g.field->height;
    tbb::parallel_for(
        tbb::blocked_range<int>(0, g.cellsY, 16), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y) {
                if (progress && progress->stopRequested())
                    return;
                for (int x = 0; x < g.cellsX; ++x) {
                    const Corners k = cellCorners(g, x, y);
                    // The gradient (per uv) over the cell ranges over a box: d h / d x is linear in
                    // y between the top and bottom edges' slopes, d h / d y in x likewise.
                    const double sx[2] = {W * (double(k.h10) - k.h00), W * (double(k.h11) - k.h01)};
                    const double sy[2] = {H * (double(k.h01) - k.h00), H * (double(k.h11) - k.h10)};
                    m_flags[static_cast<std::size_t>(y) * g.cellsX + x] =
                        fallingSectors(std::min(sx[0], sx[1]), std::max(sx[0], sx[1]),
                                       std::min(sy[0], sy[1]), std::max(sy[0], sy[1]));
                }
                if (progress)
                    progress->advance(1);
            }
        });
    m_levels.emplace_back();
    m_any.emplace_back();
    auto stopped = [progress] { return progress && progress->stopRequested(); };
    while ((m_width.back() > 1 || m_height.back() > 1) && !stopped()) {
        const int child = static_cast<int>(m_width.size()) - 1;
        const int cw = m_width.back(), ch = m_height.back();
        const int w = (cw + 1) / 2, h = (ch + 1) / 2;
        std::vector<std::uint16_t> values(static_cast<std::size_t>(w) * h * kSectors, 0);
        std::vector<std::uint16_t> any(static_cast<std::size_t>(w) * h, 0);
        tbb::parallel_for(
            tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
                for (int y = rows.begin(); y < rows.end(); ++y) {
                    if (stopped())
                        return;
                    for (int x = 0; x < w; ++x) {
                        std::uint16_t* out =
                            &values[(static_cast<std::size_t>(y) * w + x) * kSectors];
                        for (int j = 0; j < 2; ++j) {
                            for (int i = 0; i < 2; ++i) {
                                const int cx = 2 * x + i, cy = 2 * y + j;
                                if (cx >= cw || cy >= ch)
                                    continue;
                                if (child == 0) {
                                    const Sectors bits = falls(cx, cy);
                                    if (!bits)
                                        continue;
                                    // Round up: the stored value must bound the cell's maximum.
                                    const float m = cellCorners(g, cx, cy).max();
                                    auto q = static_cast<std::uint16_t>(
                                        m_scale > 0.0f ? std::min(65535.0f, std::ceil(m / m_scale))
                                                       : 0.0f);
                                    while (q < 65535 && q * m_scale < m)
                                        ++q;
                                    for (int s = 0; s < kSectors; ++s) {
                                        if ((bits >> s) & 1)
                                            out[s] = std::max(out[s], q);
                                    }
                                } else {
                                    const std::uint16_t* in =
                                        &m_levels[child][(static_cast<std::size_t>(cy) * cw + cx) *
                                                         kSectors];
                                    for (int s = 0; s < kSectors; ++s)
                                        out[s] = std::max(out[s], in[s]);
                                }
                            }
                        }
                        any[static_cast<std::size_t>(y) * w + x] =
                            *std::max_element(out, out + kSectors);
                    }
                }
            });
        m_levels.push_back(std::move(values));
        m_any.push_back(std::move(any));
        m_width.push_back(w);
        m_height.push_back(h);
    }
}

} // namespace px::cone

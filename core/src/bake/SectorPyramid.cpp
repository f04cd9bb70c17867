#include "bake/SectorPyramid.h"

#include <array>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px::cone {

ArcTable::ArcTable() {
    for (int m = 1; m < 256; ++m) {
        int bestGap = -1, bestStart = 0;
        for (int s = 0; s < 8; ++s) {
            if (!((m >> s) & 1) || ((m >> ((s + 7) & 7)) & 1))
                continue; // not the first sector of a run
            int gap = 0;
            for (int k = (s + 7) & 7; !((m >> k) & 1) && gap < 8; k = (k + 7) & 7)
                ++gap;
            if (gap > bestGap) {
                bestGap = gap;
                bestStart = s;
            }
        }
        std::uint8_t arc = 0;
        for (int i = 0; i < 8 - bestGap; ++i)
            arc |= std::uint8_t(1u << ((bestStart + i) & 7));
        fill[m] = bestGap < 0 ? 0xff : arc;
    }
}

const ArcTable kArcs;

namespace {

// Whether g . e < 0 for an edge direction e of sector k's boundary at angle 45 j degrees.
bool fallsAlong(double gx, double gy, int j) {
    switch (j & 7) {
    case 0:
        return gx < 0;
    case 1:
        return gx + gy < 0;
    case 2:
        return gy < 0;
    case 3:
        return gy - gx < 0;
    case 4:
        return -gx < 0;
    case 5:
        return -gx - gy < 0;
    case 6:
        return -gy < 0;
    default:
        return gx - gy < 0;
    }
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
                    std::uint8_t bits = 0;
                    for (int sector = 0; sector < 8; ++sector) {
                        for (int corner = 0; corner < 4 && !((bits >> sector) & 1); ++corner) {
                            const double gx = sx[corner & 1], gy = sy[corner >> 1];
                            if (fallsAlong(gx, gy, sector) || fallsAlong(gx, gy, sector + 1))
                                bits |= std::uint8_t(1u << sector);
                        }
                    }
                    m_flags[static_cast<std::size_t>(y) * g.cellsX + x] = bits;
                }
                if (progress)
                    progress->advance(1);
            }
        });
    m_levels.emplace_back();
    auto stopped = [progress] { return progress && progress->stopRequested(); };
    while ((m_width.back() > 1 || m_height.back() > 1) && !stopped()) {
        const int child = static_cast<int>(m_width.size()) - 1;
        const int cw = m_width.back(), ch = m_height.back();
        const int w = (cw + 1) / 2, h = (ch + 1) / 2;
        std::vector<std::uint16_t> values(static_cast<std::size_t>(w) * h * 8, 0);
        tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>&
                                                                    rows) {
            for (int y = rows.begin(); y < rows.end(); ++y) {
                if (stopped())
                    return;
                for (int x = 0; x < w; ++x) {
                    std::uint16_t* out = &values[(static_cast<std::size_t>(y) * w + x) * 8];
                    for (int j = 0; j < 2; ++j) {
                        for (int i = 0; i < 2; ++i) {
                            const int cx = 2 * x + i, cy = 2 * y + j;
                            if (cx >= cw || cy >= ch)
                                continue;
                            if (child == 0) {
                                const std::uint8_t bits = falls(cx, cy);
                                if (!bits)
                                    continue;
                                // Round up: the stored value must bound the cell's maximum.
                                const float m = cellCorners(g, cx, cy).max();
                                auto q = static_cast<std::uint16_t>(
                                    m_scale > 0.0f ? std::min(65535.0f, std::ceil(m / m_scale))
                                                   : 0.0f);
                                while (q < 65535 && q * m_scale < m)
                                    ++q;
                                for (int s = 0; s < 8; ++s) {
                                    if ((bits >> s) & 1)
                                        out[s] = std::max(out[s], q);
                                }
                            } else {
                                const std::uint16_t* in =
                                    &m_levels[child][(static_cast<std::size_t>(cy) * cw + cx) * 8];
                                for (int s = 0; s < 8; ++s)
                                    out[s] = std::max(out[s], in[s]);
                            }
                        }
                    }
                }
            }
        });
        m_levels.push_back(std::move(values));
        m_width.push_back(w);
        m_height.push_back(h);
    }
}

} // namespace px::cone

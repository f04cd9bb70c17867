#include "preview/VisibleRegion.h"

#include <algorithm>
#include <cmath>

namespace px::studio {

namespace {

// A cell is this many texels wide, or wider where the grid would pass kMaxCells a side.
constexpr double kCellTexels = 4.0;
constexpr int kMaxCells = 1024;
// Two neighbouring pixels whose uv differ by more than this (tiles) show different parts of the
// mesh: nothing between them is marked.
constexpr double kSeamTiles = 0.5;

} // namespace

VisibleRegion::VisibleRegion(const Image& entry, int mapWidth, int mapHeight) {
    if (entry.channels < 3)
        return;
    auto onSurface = [&](int x, int y) { return entry.at(x, y, 2) >= 0.0f; };
    double u0 = HUGE_VAL, v0 = HUGE_VAL, u1 = -HUGE_VAL, v1 = -HUGE_VAL;
    for (int y = 0; y < entry.height; ++y)
        for (int x = 0; x < entry.width; ++x)
            if (onSurface(x, y)) {
                u0 = std::min(u0, double(entry.at(x, y, 0)));
                u1 = std::max(u1, double(entry.at(x, y, 0)));
                v0 = std::min(v0, double(entry.at(x, y, 1)));
                v1 = std::max(v1, double(entry.at(x, y, 1)));
            }
    if (!(u0 <= u1 && v0 <= v1))
        return; // no surface in view
    m_cellU = std::max(kCellTexels / std::max(1, mapWidth), (u1 - u0) / (kMaxCells - 2));
    m_cellV = std::max(kCellTexels / std::max(1, mapHeight), (v1 - v0) / (kMaxCells - 2));
    // One cell of margin on every side for the growth.
    m_u0 = u0 - m_cellU;
    m_v0 = v0 - m_cellV;
    m_columns = static_cast<int>(std::floor((u1 - m_u0) / m_cellU)) + 2;
    m_rows = static_cast<int>(std::floor((v1 - m_v0) / m_cellV)) + 2;
    std::vector<unsigned char> seen(static_cast<std::size_t>(m_columns) * m_rows, 0);
    m_cells.swap(seen);
    // Each pixel, and the cells between it and its right and lower neighbours.
    for (int y = 0; y < entry.height; ++y) {
        for (int x = 0; x < entry.width; ++x) {
            if (!onSurface(x, y))
                continue;
            const double u = entry.at(x, y, 0), v = entry.at(x, y, 1);
            int i = 0, j = 0;
            if (cellOf(u, v, i, j))
                mark(i, j);
            for (const auto& [nx, ny] : {std::pair{x + 1, y}, std::pair{x, y + 1}}) {
                if (nx >= entry.width || ny >= entry.height || !onSurface(nx, ny))
                    continue;
                const double du = entry.at(nx, ny, 0) - u, dv = entry.at(nx, ny, 1) - v;
                if (std::abs(du) > kSeamTiles || std::abs(dv) > kSeamTiles)
                    continue;
                const int steps = static_cast<int>(
                    std::ceil(std::max(std::abs(du) / m_cellU, std::abs(dv) / m_cellV)));
                for (int k = 1; k <= steps; ++k)
                    if (cellOf(u + du * k / steps, v + dv * k / steps, i, j))
                        mark(i, j);
            }
        }
    }
    // Grow by one cell: a hit a few texels past the last pixel's uv is still on that surface.
    seen = m_cells;
    for (int j = 0; j < m_rows; ++j)
        for (int i = 0; i < m_columns; ++i)
            if (seen[static_cast<std::size_t>(j) * m_columns + i])
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di)
                        mark(i + di, j + dj);
}

bool VisibleRegion::cellOf(double u, double v, int& i, int& j) const {
    const double fi = std::floor((u - m_u0) / m_cellU), fj = std::floor((v - m_v0) / m_cellV);
    if (!(fi >= 0.0 && fj >= 0.0 && fi < m_columns && fj < m_rows))
        return false;
    i = static_cast<int>(fi);
    j = static_cast<int>(fj);
    return true;
}

void VisibleRegion::mark(int i, int j) {
    if (i >= 0 && j >= 0 && i < m_columns && j < m_rows)
        m_cells[static_cast<std::size_t>(j) * m_columns + i] = 1;
}

bool VisibleRegion::contains(double u, double v) const {
    int i = 0, j = 0;
    return cellOf(u, v, i, j) && m_cells[static_cast<std::size_t>(j) * m_columns + i] != 0;
}

} // namespace px::studio

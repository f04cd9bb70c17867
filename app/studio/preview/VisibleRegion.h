#pragma once
// Which part of the height field a view shows: the uv its surface covers, from a render of each
// pixel's own uv (no tracing: where its ray enters the relief). The error readout counts a pixel
// only where the exact hit lies in it (docs/meshes.md). On a mesh the relief is a locally flat
// model under each pixel's tangent plane: near a silhouette, or where the frame's lengths
// collapse (a sphere's poles), a ray runs under that plane for many tiles before the exact walk
// meets the height field, at a uv the view shows nowhere. The distance between two points of no
// visible surface says nothing about the technique, and a few such rays outweighed every other
// pixel's error.
//
// The region is a grid over the uv the view's pixels cover (unwrapped: tile + uv), each cell a
// few texels wide: a pixel marks its cell and the cells between it and its neighbours (the
// surface between two pixels is shown too), unless their uv differ by more than half a tile (a
// seam, or two parts of the mesh meeting on screen), and the marks grow by one cell.

#include "parallax/image/Image.h"

#include <vector>

namespace px::studio {

class VisibleRegion {
public:
    // `entry`: (u, v, t, -) per pixel, t < 0 where no surface was drawn (the surface output of a
    // technique that does not trace); W x H the height map's size in texels.
    VisibleRegion(const Image& entry, int mapWidth, int mapHeight);
    // Whether the uv (u, v) (tile + uv) lies on the surface the view shows.
    bool contains(double u, double v) const;
    bool empty() const { return m_columns == 0; }

private:
    bool cellOf(double u, double v, int& i, int& j) const;
    void mark(int i, int j);
    double m_u0 = 0.0, m_v0 = 0.0, m_cellU = 1.0, m_cellV = 1.0;
    int m_columns = 0, m_rows = 0;
    std::vector<unsigned char> m_cells;
};

} // namespace px::studio

#pragma once
// Sculpted tiles with known surfaces for the mesh bake's tests (tests/core/meshbake,
// tests/cli/bake): a smooth periodic ground, domes, a floating disc, open boxes with vertical
// walls, Z-up with analytic normals; and the writers the tests need beyond TestMeshes.h (binary
// PLY, a Y-up copy for glTF).

#include "TestMeshes.h"

#include <string>

namespace px::test {

struct TileRect {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
};

// z = amplitude * sin(2 pi u + phase) * cos(2 pi v), u, v the position across the tile: one
// period each way, so the surface tiles. An (n + 1) x (n + 1) vertex grid covering the tile.
TestMesh periodicGround(const TileRect& tile, int n, double amplitude, double phase);
double periodicGroundZ(const TileRect& tile, double amplitude, double phase, double x, double y);
glm::dvec3 periodicGroundNormal(const TileRect& tile, double amplitude, double phase, double x,
                                double y);

// The plane z = height over the rectangle, n x n cells.
TestMesh flatGround(const TileRect& rect, int n, double height = 0.0);

// The upper half of a sphere of `radius` centred at `centre` (its rim on z = centre.z), open
// below, normals radial.
TestMesh dome(glm::dvec3 centre, double radius, int segments, int rings);

// A disc of `segments` sides: top at z, bottom at z - thickness (facing down), a side wall.
TestMesh floatingDisc(glm::dvec2 centre, double radius, double z, double thickness, int segments);

// An open box: the top at z = height and four vertical walls down to z = 0, no bottom.
TestMesh openBox(const TileRect& rect, double height);

// Appends b's vertices and triangles to a.
void append(TestMesh& a, const TestMesh& b);

// The same mesh as a Y-up file stores it: (x, y, z) -> (x, z, -y), read back with --up y.
TestMesh toYUp(TestMesh mesh);

// Binary little-endian PLY: float x y z nx ny nz, uchar/int faces.
bool writePlyBinary(const std::string& path, const TestMesh& mesh);

} // namespace px::test

#include "parallax/bake/ConeMapReference.h"

#include "bake/ConeCells.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px {
namespace {

using namespace cone;

bool inside(int i, int n) {
    return i >= 0 && i < n;
}

// Every cell, in square rings of offsets around the apex; ring r's cells are at least r - 1
// texels away along one axis, so the scan stops once that cannot narrow the cone.
template <typename CellFn>
float ringScan(const CellGrid& g, const Apex& b, float hMax, CellFn cell) {
    if (!(b.h < hMax))
        return 1.0f;
    float c = 1.0f;
    const int rMax = std::max(g.field->width, g.field->height) + 2;
    for (int r = 1; r <= rMax; ++r) {
        if (r >= 2) {
            const float d = std::min(texelDistance(static_cast<float>(r - 1), 0.0f, g),
                                     texelDistance(0.0f, static_cast<float>(r - 1), g));
            if (d / (hMax - b.h) >= c)
                break;
        }
        for (int oy = -r; oy <= r - 1; ++oy) {
            const bool edgeRow = oy == -r || oy == r - 1;
            for (int ox = -r; ox <= r - 1; ox += edgeRow ? 1 : 2 * r - 1) {
                if (g.repeat() ? beyondPeriod(g, ox, oy)
                               : !inside(b.x + ox, g.cellsX) || !inside(b.y + oy, g.cellsY))
                    continue;
                c = cell(g, b, ox, oy, c);
            }
        }
    }
    return c;
}

// Relaxed cones with clamp also see the strips beyond the map's edges (ConeCells.h).
float stripScan(const CellGrid& g, const Apex& b, float c) {
    for (int side = 0; side < 4; ++side) {
        for (int i = 0; i < stripSegments(g, side); ++i) {
            int x, y;
            Shape shape;
            stripSegment(g, side, i, x, y, shape);
            c = relaxedCell(g, b, x - b.x, y - b.y, c, shape);
        }
    }
    return c;
}

template <typename CellFn>
ConeMap bakeBruteForce(const HeightField& field, WrapMode wrap, ConeKind kind, CellFn cell) {
    ConeMap cones(kind, field.width, field.height);
    if (field.empty())
        return cones;
    const CellGrid grid(field, wrap);
    const float hMax = field.maxHeight();
    tbb::parallel_for(tbb::blocked_range<int>(0, field.height),
                      [&](const tbb::blocked_range<int>& rows) {
                          for (int y = rows.begin(); y < rows.end(); ++y) {
                              for (int x = 0; x < field.width; ++x) {
                                  const Apex b{x, y, field.at(x, y)};
                                  float c = ringScan(grid, b, hMax, cell);
                                  if (kind == ConeKind::Relaxed && b.h < hMax)
                                      c = stripScan(grid, b, c);
                                  cones.g(x, y) = std::sqrt(finishRatio(c));
                              }
                          }
                      });
    return cones;
}

} // namespace

ConeMap bakeConservativeConesBruteForce(const HeightField& field, WrapMode wrap) {
    return bakeBruteForce(field, wrap, ConeKind::Conservative,
                          [](const CellGrid& g, const Apex& b, int ox, int oy, float c) {
                              return conservativeCell(g, b, ox, oy, c);
                          });
}

ConeMap bakeRelaxedConesBruteForce(const HeightField& field, WrapMode wrap) {
    return bakeBruteForce(field, wrap, ConeKind::Relaxed,
                          [](const CellGrid& g, const Apex& b, int ox, int oy, float c) {
                              return relaxedCell(g, b, ox, oy, c);
                          });
}

} // namespace px

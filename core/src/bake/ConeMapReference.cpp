#include "parallax/bake/ConeMapReference.h"

#include "bake/BakeKernel.h"

#include <algorithm>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px {
namespace {

using bake::BakeKernel;

bool inside(int i, int n) {
    return i >= 0 && i < n;
}

// Every cell, in square rings of offsets around the apex; ring r's cells are at least r - 1
// texels away along one axis, so the scan stops once that cannot narrow the cone. `cell` is
// the kernel's bound of one cell (cutoff: the cone so far).
template <typename CellFn> float ringScan(BakeKernel& k, glm::ivec2 b, float hb, CellFn cell) {
    if (!(hb < k.pxBakeMax))
        return 1.0f;
    float c = 1.0f;
    const glm::ivec2 cells = k.pxBakeCells();
    const int rMax = std::max(k.pxBakeSize.x, k.pxBakeSize.y) + 2;
    for (int r = 1; r <= rMax; ++r) {
        if (r >= 2) {
            const float d = std::min(k.pxBakeDistance(static_cast<float>(r - 1), 0.0f),
                                     k.pxBakeDistance(0.0f, static_cast<float>(r - 1)));
            if (d / (k.pxBakeMax - hb) >= c)
                break;
        }
        for (int oy = -r; oy <= r - 1; ++oy) {
            const bool edgeRow = oy == -r || oy == r - 1;
            for (int ox = -r; ox <= r - 1; ox += edgeRow ? 1 : 2 * r - 1) {
                if (k.pxBakeRepeat ? k.pxBakeBeyondPeriod(ox, oy)
                                   : !inside(b.x + ox, cells.x) || !inside(b.y + oy, cells.y))
                    continue;
                c = std::min(c, cell(k, b, hb, glm::ivec2(ox, oy), c));
            }
        }
    }
    return c;
}

// Relaxed cones with clamp also see the strips beyond the map's edges: every segment.
float stripScan(BakeKernel& k, glm::ivec2 b, float hb, float c) {
    for (int side = 0; side < 4; ++side) {
        for (int i = 0; i < k.pxStripSegments(side); ++i) {
            const glm::ivec4 s = k.pxStripSegment(side, i);
            c = std::min(c, k.pxBakeRelaxedAt(b, hb, glm::ivec2(s.x - b.x, s.y - b.y),
                                              glm::ivec2(s.z, s.w), c));
        }
    }
    return c;
}

template <typename CellFn>
ConeMap bakeBruteForce(const HeightField& field, WrapMode wrap, ConeKind kind, CellFn cell) {
    ConeMap cones(kind, field.width, field.height);
    if (field.empty())
        return cones;
    const bake::BakeBindings bindings(field, wrap);
    const PlaneWriter put = cones.writer(); // before the threads: SharedTexels.h
    tbb::parallel_for(tbb::blocked_range<int>(0, field.height),
                      [&](const tbb::blocked_range<int>& rows) {
                          BakeKernel k;
                          static_cast<bake::BakeBindings&>(k) = bindings;
                          for (int y = rows.begin(); y < rows.end(); ++y) {
                              for (int x = 0; x < field.width; ++x) {
                                  const glm::ivec2 b(x, y);
                                  const float hb = field.at(x, y);
                                  float c = ringScan(k, b, hb, cell);
                                  if (kind == ConeKind::Relaxed && hb < k.pxBakeMax)
                                      c = stripScan(k, b, hb, c);
                                  put.at(x, y) = std::sqrt(k.pxBakeFinish(c));
                              }
                          }
                      });
    return cones;
}

} // namespace

ConeMap bakeConservativeConesBruteForce(const HeightField& field, WrapMode wrap) {
    return bakeBruteForce(field, wrap, ConeKind::Conservative,
                          [](BakeKernel& k, glm::ivec2 b, float hb, glm::ivec2 o, float c) {
                              return k.pxBakeConservativeAt(b, hb, o, c);
                          });
}

ConeMap bakeRelaxedConesBruteForce(const HeightField& field, WrapMode wrap) {
    return bakeBruteForce(field, wrap, ConeKind::Relaxed,
                          [](BakeKernel& k, glm::ivec2 b, float hb, glm::ivec2 o, float c) {
                              return k.pxBakeRelaxedAt(b, hb, o, k.pxBakeSpan(), c);
                          });
}

} // namespace px

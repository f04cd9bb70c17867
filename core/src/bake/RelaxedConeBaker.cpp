// Relaxed cone maps on the CPU: the kernel of shaders/bake/relaxed.glsl (the GPU's, compiled as
// C++) over 4 x 4 tiles of texels, every core. Each tile is seeded with the cells that set the
// cones of the tile to its left and the tile above (neighbouring cones are set by nearly the same
// cells); seeds only make the search shorter, never change a cone, so the output is the same for
// any thread count and equals the GPU's.

#include "bake/BakeKernel.h"
#include "bake/BakeProgress.h"
#include "parallax/bake/ConeMapBaker.h"

#include <cstdint>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <vector>

namespace px {
namespace {

constexpr int kTileW = PX_TILE_W, kTileH = PX_TILE_H;

// A tile row's share of the progress bar against one cell row of the pyramid's set-up.
constexpr int kTileRowWork = 200;

} // namespace

Result<ConeMap> bakeRelaxedConeMap(const HeightField& field, WrapMode wrap,
                                   const BakeControl& control) {
    if (field.empty())
        return Error{"the height map is empty"};
    // Work units: a cell row of the pyramid's set-up is 1, a tile row (4 texel rows)
    // kTileRowWork, so the set-up is a few percent of the bar, as it is of the time.
    const int tileRows = (field.height + kTileH - 1) / kTileH;
    BakeProgress progress(control,
                          std::int64_t(field.height) + 1 + std::int64_t(tileRows) * kTileRowWork);
    const bake::FallPyramid fall(field, wrap, &progress);
    if (progress.stopRequested())
        return cancelledError();
    const bake::EdgeStrips strips(field, wrap);
    bake::BakeBindings bindings(field, wrap);
    bindings.fall = &fall;
    bindings.strips = &strips;
    bindings.pxFallTop = fall.top();
    bindings.pxFallUnit = fall.unit();
    ConeMap cones(ConeKind::Relaxed, field.width, field.height);
    const PlaneWriter put = cones.writer(); // before the threads: SharedTexels.h
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tileRows, 4), [&](const tbb::blocked_range<int>& rows) {
            bake::BakeKernel kernel;
            static_cast<bake::BakeBindings&>(kernel) = bindings;
            // The witnesses of the tile row above, per texel column (none above a range's first
            // row).
            std::vector<glm::ivec3> above(static_cast<std::size_t>(field.width), glm::ivec3(0));
            for (int r = rows.begin(); r < rows.end(); ++r) {
                // Polled per tile and reported per tile row: a cancel stops within a tile row.
                const int ty = r * kTileH, th = std::min(kTileH, field.height - ty);
                for (int j = 0; j < kTileH; ++j)
                    kernel.pxSeedRow[j] = glm::ivec3(0);
                for (int tx = 0; tx < field.width; tx += kTileW) {
                    if (progress.stopRequested())
                        return;
                    const int tw = std::min(kTileW, field.width - tx);
                    for (int i = 0; i < kTileW; ++i)
                        kernel.pxSeedColumn[i] =
                            i < tw
                                ? above[static_cast<std::size_t>(tx) + static_cast<std::size_t>(i)]
                                : glm::ivec3(0);
                    kernel.pxRelaxedTile(glm::ivec2(tx, ty), glm::ivec2(tw, th));
                    for (int k = 0; k < tw * th; ++k)
                        put.at(tx + k % tw, ty + k / tw) = kernel.pxRelaxedResult(k);
                    for (int j = 0; j < th; ++j)
                        kernel.pxSeedRow[j] = kernel.pxTileWitness[j * tw + tw - 1];
                    for (int i = 0; i < tw; ++i)
                        above[static_cast<std::size_t>(tx) + static_cast<std::size_t>(i)] =
                            kernel.pxTileWitness[(th - 1) * tw + i];
                }
                progress.advance(kTileRowWork);
            }
        });
    if (progress.stopRequested())
        return cancelledError();
    progress.finish();
    return cones;
}

} // namespace px

// Quick conservative cone maps on the CPU: the kernel of shaders/bake/quick.glsl (the GPU's,
// compiled as C++) per texel, every core.

#include "bake/BakeKernel.h"
#include "bake/BakeProgress.h"
#include "parallax/bake/ConeMapBaker.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace px {

Result<ConeMap> bakeQuickConeMap(const HeightField& field, WrapMode wrap,
                                 const BakeControl& control) {
    if (field.empty())
        return Error{"the height map is empty"};
    const bake::CellPyramid pyramid(field, wrap);
    bake::BakeBindings bindings(field, wrap);
    bindings.cells = &pyramid;
    bindings.pxCellLevels = pyramid.levels();
    ConeMap cones(ConeKind::Conservative, field.width, field.height);
    const PlaneWriter put = cones.writer(); // before the threads: SharedTexels.h
    BakeProgress progress(control, field.height);
    tbb::parallel_for(tbb::blocked_range<int>(0, field.height, 2),
                      [&](const tbb::blocked_range<int>& rows) {
                          if (progress.stopRequested())
                              return;
                          bake::BakeKernel kernel;
                          static_cast<bake::BakeBindings&>(kernel) = bindings;
                          for (int y = rows.begin(); y < rows.end(); ++y) {
                              for (int x = 0; x < field.width; ++x)
                                  put.at(x, y) = kernel.pxQuickResult(glm::ivec2(x, y));
                          }
                          progress.advance(rows.size());
                      });
    if (progress.stopRequested())
        return cancelledError();
    progress.finish();
    return cones;
}

} // namespace px

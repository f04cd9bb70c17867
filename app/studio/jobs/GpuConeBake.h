#pragma once
// A cone bake on the GPU from a bake's worker thread: a context sharing the viewports'
// (SharedGlContext.h) runs the kernels of shaders/bake/ (GpuConeBaker), in slices of a few
// milliseconds so that the viewports draw between them. The maps equal the CPU's (to the bit on
// llvmpipe). Where no such context can be made (Qt's offscreen platform, a driver without compute
// shaders) the result says why and the caller bakes on the CPU.

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <QString>
#include <memory>

class QOffscreenSurface;

namespace px::studio {

// `surface`: made on the GUI thread (workerSurface()), null where the viewports share no context.
// `renderer` receives the GL renderer that baked.
Result<ConeMap> bakeConeOnGpu(const HeightField& field, WrapMode wrap, ConeKind kind,
                              const BakeControl& control,
                              const std::shared_ptr<QOffscreenSurface>& surface, QString* renderer);

} // namespace px::studio

#include "jobs/GpuConeBake.h"

#include "jobs/SharedGlContext.h"
#include "parallax/render/GpuConeBaker.h" // parallax-render

#include <QOffscreenSurface>
#include <QOpenGLContext>

namespace px::studio {

Result<ConeMap> bakeConeOnGpu(const HeightField& field, WrapMode wrap, ConeKind kind,
                              const BakeControl& control,
                              const std::shared_ptr<QOffscreenSurface>& surface,
                              QString* renderer) {
    if (!surface)
        return Error{"the viewports' OpenGL context is not shared"};
    Result<std::shared_ptr<QOpenGLContext>> context = sharedViewportContext(surface);
    if (!context)
        return context.error();
    GpuBakeInfo info;
    Result<ConeMap> cones = [&] {
        GpuConeBaker baker;            // its programs go before the context does
        baker.sliceMilliseconds = 8.0; // a frame's share: the viewports draw between slices
        return baker.bake(field, wrap, kind, control, &info);
    }();
    if (cones && renderer)
        *renderer = QString::fromStdString(info.renderer);
    return cones;
}

} // namespace px::studio

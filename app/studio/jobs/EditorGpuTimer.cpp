#include "jobs/EditorGpuTimer.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QSurfaceFormat>

namespace px::studio {

namespace {

// A context shared with the viewports', current on the calling thread, or why there is none.
Result<BenchContext> sharedContext(const std::shared_ptr<QOffscreenSurface>& surface) {
    QOpenGLContext* viewports = QOpenGLContext::globalShareContext();
    if (!viewports)
        return Error{"the viewports' OpenGL context is not shared"};
    // The surface goes with the context: it must outlive it.
    std::shared_ptr<QOpenGLContext> context(new QOpenGLContext, [surface](QOpenGLContext* c) {
        c->doneCurrent();
        delete c;
    });
    context->setFormat(viewports->format());
    context->setShareContext(viewports);
    if (!context->create() || !QOpenGLContext::areSharing(context.get(), viewports))
        return Error{"no OpenGL context could share the viewports'"};
    if (!surface->isValid() || !context->makeCurrent(surface.get()))
        return Error{"the shared OpenGL context could not be made current"};
    return BenchContext{context, "the editor's OpenGL context (shared with the viewports)"};
}

} // namespace

GpuFrameTimer editorGpuTimer(const GpuBenchOptions& options) {
    // Made here on the GUI thread, as Qt requires of a surface another thread draws on; deleted
    // there too (deleteLater), whichever thread lets it go.
    std::shared_ptr<QOffscreenSurface> surface(new QOffscreenSurface,
                                               [](QOffscreenSurface* s) { s->deleteLater(); });
    if (QOpenGLContext* viewports = QOpenGLContext::globalShareContext())
        surface->setFormat(viewports->format());
    surface->create();
    return lazyGpuBenchTimer(options, [surface]() -> Result<BenchContext> {
        Result<BenchContext> shared = sharedContext(surface);
        if (shared)
            return shared;
        Result<BenchContext> headless = headlessBenchContext();
        if (!headless)
            return Error{shared.error().message + "; " + headless.error().message};
        headless->name += " (" + shared.error().message + ")";
        return headless;
    });
}

} // namespace px::studio

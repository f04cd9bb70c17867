#include "jobs/SharedGlContext.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QSurfaceFormat>

namespace px::studio {

std::shared_ptr<QOffscreenSurface> workerSurface() {
    std::shared_ptr<QOffscreenSurface> surface(new QOffscreenSurface,
                                               [](QOffscreenSurface* s) { s->deleteLater(); });
    if (QOpenGLContext* viewports = QOpenGLContext::globalShareContext())
        surface->setFormat(viewports->format());
    surface->create();
    return surface;
}

Result<std::shared_ptr<QOpenGLContext>>
sharedViewportContext(const std::shared_ptr<QOffscreenSurface>& surface) {
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
    return context;
}

} // namespace px::studio

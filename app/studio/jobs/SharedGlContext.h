#pragma once
// OpenGL contexts for worker threads that share the viewports' objects (Qt's global share
// context, AA_ShareOpenGLContexts): what a worker makes there, a view can draw, and the reverse.

#include "parallax/Result.h"

#include <memory>

class QOffscreenSurface;
class QOpenGLContext;

namespace px::studio {

// The surface a worker's context is made current on. Call on the GUI thread (Qt makes surfaces
// there); it is deleted there too, whichever thread lets it go.
std::shared_ptr<QOffscreenSurface> workerSurface();

// A context sharing the viewports', made and current on the calling thread, or why there is none
// (no shared context on Qt's offscreen platform). It keeps `surface` alive and is done current
// and deleted when let go, on the thread that made it.
Result<std::shared_ptr<QOpenGLContext>>
sharedViewportContext(const std::shared_ptr<QOffscreenSurface>& surface);

} // namespace px::studio

#include "jobs/EditorGpuTimer.h"

#include "jobs/SharedGlContext.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>

namespace px::studio {

GpuFrameTimer editorGpuTimer(const GpuBenchOptions& options) {
    std::shared_ptr<QOffscreenSurface> surface = workerSurface(); // on the GUI thread
    return lazyGpuBenchTimer(options, [surface]() -> Result<BenchContext> {
        Result<std::shared_ptr<QOpenGLContext>> shared = sharedViewportContext(surface);
        if (shared)
            return BenchContext{*shared, "the editor's OpenGL context (shared with the viewports)"};
        Result<BenchContext> headless = headlessBenchContext();
        if (!headless)
            return Error{shared.error().message + "; " + headless.error().message};
        headless->name += " (" + shared.error().message + ")";
        return headless;
    });
}

} // namespace px::studio

#pragma once
// The Compare panel's GPU timer. The sweep is timed on an OpenGL context shared with the
// viewports' (Qt's global share context): contexts share only on one device and driver, so this
// is the GPU that draws the preview. It is made on the bench's worker thread, because timing on
// the viewports' own context would freeze the editor for the whole sweep. Where no context can be
// shared (Qt's offscreen platform), a headless EGL context times instead and the label says so.

#include "parallax/render/GpuBenchTimer.h"

namespace px::studio {

// Call on the GUI thread (it makes the offscreen surface the worker's context draws on).
GpuFrameTimer editorGpuTimer(const GpuBenchOptions& options);

} // namespace px::studio

#pragma once
// Shown when the system has no usable OpenGL 4.3: says what was found and what is needed, and
// offers Mesa's software renderer (a restart with LIBGL_ALWAYS_SOFTWARE=1, which provides 4.5 on
// any machine) or going on without the live preview. Never a crash.

#include "preview/GlSupport.h"

class QWidget;

namespace px::studio {

enum class GlChoice { RestartInSoftware, ContinueWithoutPreview, Quit };

GlChoice askAboutMissingGl(const GlProbe& probe, QWidget* parent = nullptr);

// Starts this program again with the same arguments and LIBGL_ALWAYS_SOFTWARE=1. False if it
// could not be started.
bool restartWithSoftwareRendering();

} // namespace px::studio

#pragma once
// Whether the live preview can run: OpenGL 4.3 core on a platform that can show GL widgets.
// Qt 6.4's offscreen platform crashes when a QOpenGLWidget is shown (docs/platform.md), and a
// driver below 4.3 cannot run the techniques; in both cases the editor shows a placeholder instead.

#include <QString>

namespace px::studio {

inline constexpr int kRequiredGlMajor = 4;
inline constexpr int kRequiredGlMinor = 3;

struct GlProbe {
    bool usable = false;
    bool offscreenPlatform = false; // no windows to show GL in: a placeholder, no dialog
    int major = 0;                  // the version found (0 when no context at all)
    int minor = 0;
    QString renderer;      // GL_RENDERER
    QString reason;        // why it is not usable, as a sentence
    bool software() const; // a software rasteriser (jobs/BakeDevice.h): llvmpipe, SwiftShader...
};

// Sets the default surface format the preview asks for (4.3 core, depth, sRGB-capable) and makes
// every context share with Qt's global one (the Compare panel times on a context shared with the
// viewports': jobs/EditorGpuTimer.h). Must run before QApplication is constructed.
void setUpOpenGl();

// Probes once (cached): creates a context of the default format on an offscreen surface and
// reads its version. Needs a QGuiApplication.
const GlProbe& probeOpenGl();

// The sentence the "no usable OpenGL" dialog shows.
QString glUnavailableMessage(const GlProbe& probe);

} // namespace px::studio

#include "preview/GlSupport.h"

#include "jobs/BakeDevice.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>

namespace px::studio {

bool GlProbe::software() const {
    return isSoftwareRasteriser(renderer);
}

void setUpOpenGl() {
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(kRequiredGlMajor, kRequiredGlMinor);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    QSurfaceFormat::setDefaultFormat(format);
}

namespace {

GlProbe runProbe() {
    GlProbe probe;
    const QString platform = QGuiApplication::platformName();
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal")) {
        probe.offscreenPlatform = true;
        probe.reason = QObject::tr("The \"%1\" platform shows no OpenGL windows.").arg(platform);
        return probe;
    }
    QOffscreenSurface surface;
    surface.setFormat(QSurfaceFormat::defaultFormat());
    surface.create();
    QOpenGLContext context;
    context.setFormat(QSurfaceFormat::defaultFormat());
    bool ok = context.create() && context.makeCurrent(&surface);
    if (!ok) {
        // Ask for whatever the driver has, to say what was found.
        QOpenGLContext fallback;
        QSurfaceFormat any;
        fallback.setFormat(any);
        if (fallback.create() && fallback.makeCurrent(&surface)) {
            probe.major = fallback.format().majorVersion();
            probe.minor = fallback.format().minorVersion();
            probe.renderer = QString::fromLatin1(
                reinterpret_cast<const char*>(fallback.functions()->glGetString(GL_RENDERER)));
            fallback.doneCurrent();
        }
        probe.reason = probe.major > 0 ? QObject::tr("The driver offers OpenGL %1.%2 only.")
                                             .arg(probe.major)
                                             .arg(probe.minor)
                                       : QObject::tr("No OpenGL context could be created.");
        return probe;
    }
    const QSurfaceFormat got = context.format();
    probe.major = got.majorVersion();
    probe.minor = got.minorVersion();
    probe.renderer = QString::fromLatin1(
        reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER)));
    context.doneCurrent();
    const bool recentEnough = probe.major > kRequiredGlMajor ||
                              (probe.major == kRequiredGlMajor && probe.minor >= kRequiredGlMinor);
    const bool core = got.profile() == QSurfaceFormat::CoreProfile || probe.major >= 4;
    probe.usable = recentEnough && core;
    if (!probe.usable)
        probe.reason =
            QObject::tr("The driver offers OpenGL %1.%2 only.").arg(probe.major).arg(probe.minor);
    return probe;
}

} // namespace

const GlProbe& probeOpenGl() {
    static const GlProbe probe = runProbe();
    return probe;
}

QString glUnavailableMessage(const GlProbe& probe) {
    const QString found =
        probe.major > 0
            ? QObject::tr("OpenGL %1.%2%3")
                  .arg(probe.major)
                  .arg(probe.minor)
                  .arg(probe.renderer.isEmpty() ? QString()
                                                : QStringLiteral(" (%1)").arg(probe.renderer))
            : QObject::tr("no OpenGL at all");
    return QObject::tr("The live preview needs OpenGL %1.%2 (core profile); this system offers %3.")
        .arg(kRequiredGlMajor)
        .arg(kRequiredGlMinor)
        .arg(found);
}

} // namespace px::studio

#include "Studio.h"

#include "preview/GlSupport.h"
#include "preview/GlUnavailableDialog.h"
#include "preview/Viewport.h"
#include "preview/ViewportGrid.h"
#include "window/MainWindow.h"
#include "window/Screenshot.h"
#include "window/StudioOptions.h"

#include <QApplication>
#include <QIcon>
#include <QRegularExpression>
#include <cstdio>

namespace px::studio {

namespace {

// Each shown viewport's figures, one line each, as under the views.
QString viewportFigures(MainWindow& window) {
    QString text;
    ViewportGrid* grid = window.viewports();
    for (int i = 0; i < grid->layoutCount(); ++i) {
        QString line = grid->viewport(i)->statsText();
        line.replace(QStringLiteral("<br>"), QStringLiteral(" · "));
        line.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
        text += QStringLiteral("viewport %1: %2\n").arg(i + 1).arg(line);
    }
    return text;
}

} // namespace

int runStudio(int argc, char** argv) {
    setUpOpenGl();
    // Fractional scale factors (125 %, 150 %) as they are, not rounded: sharp text and views.
    QGuiApplication::setHighDpiScaleFactorRoundingPolicy(
        Qt::HighDpiScaleFactorRoundingPolicy::PassThrough);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("parallax-studio"));
    QApplication::setApplicationName(QStringLiteral("parallax-studio"));
    QApplication::setApplicationDisplayName(QStringLiteral("Parallax Studio"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/parallax-studio.svg")));

    QStringList arguments;
    for (int i = 1; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    if (arguments.contains(QLatin1String("--help")) || arguments.contains(QLatin1String("-h"))) {
        std::fputs(qPrintable(studioUsage()), stdout);
        return 0;
    }
    Result<StudioOptions> options = parseStudioOptions(arguments);
    if (!options) {
        std::fprintf(stderr, "error: %s\n", options.error().message.c_str());
        return 2;
    }

    const GlProbe& gl = probeOpenGl();
    QString liveReason;
    if (!gl.usable) {
        liveReason = gl.offscreenPlatform ? gl.reason : glUnavailableMessage(gl);
        if (!options->screenshot.isEmpty()) {
            std::fprintf(stderr, "error: %s\n", qPrintable(liveReason));
            return 1;
        }
        if (!gl.offscreenPlatform) {
            switch (askAboutMissingGl(gl)) {
            case GlChoice::RestartInSoftware:
                if (restartWithSoftwareRendering())
                    return 0;
                std::fprintf(stderr, "error: could not restart with software rendering\n");
                break;
            case GlChoice::ContinueWithoutPreview:
                break;
            case GlChoice::Quit:
                return 1;
            }
        }
    }

    MainWindow window(liveReason);
    const bool screenshot = !options->screenshot.isEmpty();
    if (screenshot) {
        window.setInteractive(false);
        QObject::connect(&window, &MainWindow::problemShown, [](const QString& message) {
            std::fprintf(stderr, "error: %s\n", qPrintable(message));
        });
    }
    const bool opened = !options->file.isEmpty() && window.openFile(options->file);
    if (!opened && !options->file.isEmpty() && screenshot)
        return 1;
    if (!opened) // no file, or it could not be opened (the message says why): the sample
        window.newSample(options->sample, options->sampleSize);
    // A screenshot reads the first uv set, whatever the settings remember: the same every time.
    if (!options->mesh.isEmpty() &&
        !window.loadMesh(options->mesh, screenshot ? 0 : MainWindow::kRememberedUvSet) &&
        screenshot)
        return 1;
    if (!options->environment.isEmpty() && !window.setEnvironment(options->environment) &&
        screenshot)
        return 1;
    if (screenshot) {
        window.resize(options->windowSize);
        applyViewOptions(window, *options);
        window.show();
        QSize pixels;
        const QString error = takeScreenshot(window, options->screenshot, &pixels);
        if (!error.isEmpty()) {
            std::fprintf(stderr, "error: %s\n", qPrintable(error));
            return 1;
        }
        std::printf("wrote %s (%dx%d pixels)\n", qPrintable(options->screenshot), pixels.width(),
                    pixels.height());
        std::fputs(qPrintable(viewportFigures(window)), stdout);
        return 0;
    }
    window.restoreLayout();
    if (options->layout != 0)
        applyViewOptions(window, *options);
    window.show();
    return app.exec();
}

} // namespace px::studio

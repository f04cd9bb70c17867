#include "window/Screenshot.h"

#include "jobs/Baking.h"
#include "model/MaterialDocument.h"
#include "preview/PreviewWidget.h"
#include "preview/Viewport.h"
#include "preview/ViewportGrid.h"
#include "window/MainWindow.h"
#include "window/StudioOptions.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QEventLoop>
#include <QImageWriter>
#include <QSaveFile>
#include <QTimer>

namespace px::studio {

namespace {

// Runs the event loop until `done` holds or the deadline passes.
bool waitFor(const std::function<bool()>& done, QDeadlineTimer deadline) {
    while (!done()) {
        if (deadline.hasExpired())
            return false;
        QEventLoop loop;
        QTimer::singleShot(20, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return true;
}

} // namespace

void applyViewOptions(MainWindow& window, const StudioOptions& options) {
    ViewportGrid* grid = window.viewports();
    if (options.layout != 0)
        grid->setLayoutCount(options.layout);
    MaterialDocument* doc = window.document();
    // Cone techniques need their maps: bake them first (in the background, waited for).
    bool cone = false, relaxed = false;
    for (Technique t : options.techniques) {
        cone |= info(t).needsConeMap && !doc->state().hasMap(MapKind::Cone);
        relaxed |= info(t).needsRelaxedConeMap && !doc->state().hasMap(MapKind::RelaxedCone);
    }
    if (cone)
        window.startBake(BakeKind::Cone);
    if (relaxed)
        window.startBake(BakeKind::RelaxedCone);
    waitFor([&] { return !window.baker()->isBusy(); }, QDeadlineTimer(600000));
    for (std::size_t i = 0; i < options.techniques.size(); ++i) {
        const Technique t = options.techniques[i];
        doc->edit(QStringLiteral("Screenshot view"), [&](DocumentState& s) {
            s.setView(static_cast<int>(i), {t, info(t).defaults});
        });
    }
}

QString takeScreenshot(MainWindow& window, const QString& file, QSize* pixels, int timeoutMs) {
    const QDeadlineTimer deadline(timeoutMs);
    ViewportGrid* grid = window.viewports();
    auto settled = [&] {
        for (int i = 0; i < grid->layoutCount(); ++i) {
            PreviewWidget* preview = grid->viewport(i)->preview();
            if (!preview || !preview->renderError().isEmpty())
                continue; // nothing to wait for: the viewport says why it does not draw
            if (preview->framesRendered() == 0 || !preview->stats().valid)
                return false;
        }
        return true;
    };
    if (!waitFor(settled, deadline))
        return QObject::tr("the viewports did not finish drawing within %1 s")
            .arg(timeoutMs / 1000);
    // One more frame each, so the figures just measured are in the picture.
    QCoreApplication::processEvents();
    const QImage image = window.grab().toImage();
    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly))
        return QObject::tr("%1: cannot write (%2)").arg(file, out.errorString());
    QImageWriter writer(&out, "png");
    if (!writer.write(image)) {
        out.cancelWriting();
        return QObject::tr("%1: %2").arg(file, writer.errorString());
    }
    if (!out.commit())
        return QObject::tr("%1: cannot write (%2)").arg(file, out.errorString());
    if (pixels)
        *pixels = image.size();
    return {};
}

} // namespace px::studio

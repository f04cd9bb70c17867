// MainWindow: pictures out — the active view or every view as a PNG at any size, and a turntable
// of the active view with progress and Cancel — rendered offscreen on the views' own contexts,
// written atomically.

#include "parallax/image/ImageSet.h"
#include "preview/PreviewWidget.h"
#include "preview/Viewport.h"
#include "preview/ViewportGrid.h"
#include "widgets/FileDialogs.h"
#include "window/MainWindow.h"

#include <QCoreApplication>
#include <QInputDialog>
#include <QProgressDialog>
#include <QRegularExpression>
#include <QStatusBar>

namespace px::studio {

namespace {

const QString kPngFilter = QObject::tr("PNG images (*.png)");

ImageWriteOptions pngOptions() {
    ImageWriteOptions png;
    png.format = PixelFormat::UInt8;
    png.srgb = true; // the colour output is sRGB-encoded
    return png;
}

// Copies `tile` into `into` with its top-left corner at (x, y).
void place(Image& into, const Image& tile, int x, int y) {
    const ImageWriter put = into.writer();
    for (int j = 0; j < tile.height; ++j)
        for (int i = 0; i < tile.width; ++i)
            for (int c = 0; c < into.channels; ++c)
                put.at(x + i, y + j, c) = tile.at(i, j, std::min(c, tile.channels - 1));
}

} // namespace

bool MainWindow::saveViewImage(const QString& file, QSize size, bool allViews) {
    const int views = allViews ? m_viewports->layoutCount() : 1;
    const int columns = views == 4 ? 2 : views, rows = views == 4 ? 2 : 1;
    Image picture(size.width() * columns, size.height() * rows, 4);
    for (int v = 0; v < views; ++v) {
        Viewport* viewport = m_viewports->viewport(allViews ? v : m_viewports->activeViewport());
        Result<Image> image = viewport->preview()->renderImage(viewport->preview()->scene(), size);
        if (!image) {
            showProblem(tr("Cannot save the picture"),
                        file + QStringLiteral(": ") +
                            QString::fromStdString(image.error().message));
            return false;
        }
        place(picture, *image, (v % columns) * size.width(), (v / columns) * size.height());
    }
    if (Status s = writeImage(file.toStdString(), picture, pngOptions()); !s) {
        showProblem(tr("Cannot save the picture"), QString::fromStdString(s.error().message));
        return false;
    }
    statusBar()->showMessage(
        tr("Saved %1 (%2 x %3).").arg(file).arg(picture.width).arg(picture.height), 8000);
    return true;
}

bool MainWindow::saveTurntable(const QString& file, QSize size, int frames) {
    Viewport* viewport = m_viewports->viewport(m_viewports->activeViewport());
    const PreviewScene scene = viewport->preview()->scene();
    const std::vector<std::string> files = numberedFiles(file.toStdString(), frames);
    // Frames render on the GUI thread (the view's GL context lives there), one per turn of the
    // event loop: between frames the window repaints and Cancel is heard. The set is staged under
    // temporary names and renamed only once complete, so a cancel leaves nothing behind.
    QProgressDialog progress(this);
    progress.setWindowTitle(tr("Turntable"));
    progress.setWindowModality(Qt::WindowModal);
    progress.setRange(0, frames);
    progress.setMinimumDuration(0);
    progress.setAutoClose(false);
    progress.setAutoReset(false);
    progress.show();
    const Status s = writeImageSet(
        files,
        [&](int i) -> Result<Image> {
            progress.setLabelText(tr("Rendering frame %1 of %2…").arg(i + 1).arg(frames));
            progress.setValue(i);
            QCoreApplication::processEvents();
            if (progress.wasCanceled())
                return Error{"turntable cancelled", ErrorKind::Cancelled, {}};
            PreviewScene turned = scene;
            turned.view.camera.azimuthDeg +=
                360.0f * static_cast<float>(i) / static_cast<float>(frames);
            return viewport->preview()->renderImage(turned, size);
        },
        pngOptions());
    progress.setValue(frames);
    if (!s && s.error().cancelled()) {
        statusBar()->showMessage(tr("Turntable cancelled; no frames written."), 8000);
        return false;
    }
    if (!s) {
        showProblem(tr("Cannot save the turntable"), QString::fromStdString(s.error().message));
        return false;
    }
    statusBar()->showMessage(
        tr("Saved %1 turntable frames: %2 … %3.")
            .arg(frames)
            .arg(QString::fromStdString(files.front()), QString::fromStdString(files.back())),
        8000);
    return true;
}

// File > Save View/All Views/Turntable: a file, then the size (the view's own by default).
void MainWindow::picturesDialog(PictureKind kind) {
    const QString file =
        askSaveFile(this, FileKind::Picture,
                    kind == PictureKind::Turntable ? tr("Save Turntable") : tr("Save Picture"),
                    QStringLiteral("view.png"), kPngFilter);
    if (file.isEmpty())
        return;
    const QWidget* view = m_viewports->viewport(m_viewports->activeViewport())->preview();
    const QSize own = view->size() * view->devicePixelRatioF();
    bool ok = false;
    const QString text = QInputDialog::getText(
        this, tr("Picture Size"), tr("Width x height in pixels (per view):"), QLineEdit::Normal,
        QStringLiteral("%1x%2").arg(own.width()).arg(own.height()), &ok);
    if (!ok)
        return;
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("^\\s*(\\d+)\\s*x\\s*(\\d+)\\s*$")).match(text);
    const int w = m.hasMatch() ? m.captured(1).toInt() : 0,
              h = m.hasMatch() ? m.captured(2).toInt() : 0;
    if (w < 1 || h < 1 || w > 16384 || h > 16384) {
        showProblem(tr("Cannot save the picture"),
                    tr("\"%1\" is not WIDTHxHEIGHT with sides 1 to 16384.").arg(text));
        return;
    }
    if (kind == PictureKind::Turntable) {
        const int frames =
            QInputDialog::getInt(this, tr("Turntable"), tr("Frames around:"), 24, 1, 3600, 1, &ok);
        if (ok)
            saveTurntable(file, QSize(w, h), frames);
        return;
    }
    saveViewImage(file, QSize(w, h), kind == PictureKind::AllViews);
}

} // namespace px::studio

#pragma once
// What the editor's GUI tests share: a small window on a small sample, waiting for frames and
// figures, and dropping files on a widget the way a file manager does.

#include "model/MaterialDocument.h"
#include "preview/GlSupport.h"
#include "preview/PreviewWidget.h"
#include "preview/Viewport.h"
#include "preview/ViewportGrid.h"
#include "window/MainWindow.h"

#include <QCoreApplication>
#include <QDir>
#include <QDropEvent>
#include <QImage>
#include <QMimeData>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>
#include <cstdlib>
#include <memory>

namespace px::studio::test {

// Keeps the tests' recent files out of the user's settings.
inline void isolateSettings(const QTemporaryDir& dir) {
    QCoreApplication::setOrganizationName(QStringLiteral("parallax-studio-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("parallax-studio-tests"));
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir.path());
}

// What the editor's GL tests start from: OpenGL set up before the application exists (QTEST_MAIN
// calls initMain()) and settings of their own in m_dir. Their initTestCase() checks
// glReady(), which fails the test saying why where there is no OpenGL 4.3.
class GlWindowTest : public QObject {
public:
    static void initMain() { setUpOpenGl(); }

protected:
    bool glReady() {
        isolateSettings(m_dir);
        if (!probeOpenGl().usable)
            qWarning("%s", qPrintable(probeOpenGl().reason));
        return probeOpenGl().usable;
    }
    QTemporaryDir m_dir;
};

// A window on the built-in bricks at `size` texels, `layout` viewports, shown and exposed.
// Problems go to lastProblem() unless `interactive`.
inline std::unique_ptr<MainWindow> makeWindow(int layout = 1, int size = 64,
                                              bool interactive = false) {
    const GlProbe& gl = probeOpenGl();
    auto window = std::make_unique<MainWindow>(gl.usable ? QString() : gl.reason);
    window->setInteractive(interactive);
    window->newSample(ProceduralMap::Bricks, size);
    window->viewports()->setLayoutCount(layout);
    window->resize(layout == 1 ? 900 : 1100, 560); // views well under 512 x 512
    window->show();
    window->activateWindow();
    if (!QTest::qWaitForWindowExposed(window.get()))
        return nullptr;
    return window;
}

// Waits until the preview has drawn a frame after now and measured its view. It asks for that
// frame: a view already drawn and measured (while another view was waited for) draws no more.
inline bool waitForFigures(PreviewWidget* preview, int timeoutMs = 30000) {
    const int frames = preview->framesRendered();
    preview->update();
    return QTest::qWaitFor(
        [&] { return preview->framesRendered() > frames && preview->stats().valid; }, timeoutMs);
}

// Waits until the preview has drawn at least one frame more than `frames`.
inline bool waitForFrame(PreviewWidget* preview, int frames, int timeoutMs = 30000) {
    preview->update();
    return QTest::qWaitFor([&] { return preview->framesRendered() > frames; }, timeoutMs);
}

// Pixels whose colour differs by more than a few levels.
inline int changedPixels(const QImage& a, const QImage& b) {
    if (a.size() != b.size())
        return a.width() * a.height();
    const QImage x = a.convertToFormat(QImage::Format_RGB32);
    const QImage y = b.convertToFormat(QImage::Format_RGB32);
    int changed = 0;
    for (int j = 0; j < x.height(); ++j) {
        const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(j));
        const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(j));
        for (int i = 0; i < x.width(); ++i) {
            const int d = std::abs(qRed(p[i]) - qRed(q[i])) +
                          std::abs(qGreen(p[i]) - qGreen(q[i])) +
                          std::abs(qBlue(p[i]) - qBlue(q[i]));
            changed += d > 12;
        }
    }
    return changed;
}

// Drops local files on `target` as a file manager would: drag enter, then drop.
inline bool dropFiles(QWidget* target, const QStringList& files) {
    QMimeData mime;
    QList<QUrl> urls;
    for (const QString& f : files)
        urls << QUrl::fromLocalFile(f);
    mime.setUrls(urls);
    const QPointF at(target->width() / 2.0, target->height() / 2.0);
    QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(target, &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(target, &drop);
    return drop.isAccepted();
}

// Counts the events of one type that reach the objects it is installed on.
struct EventCounter : QObject {
    explicit EventCounter(QEvent::Type counted) : type(counted) {}
    QEvent::Type type;
    int count = 0;
    bool eventFilter(QObject*, QEvent* e) override {
        count += e->type() == type ? 1 : 0;
        return false;
    }
};

} // namespace px::studio::test

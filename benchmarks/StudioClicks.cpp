// Clicks right after a layout change, as an artist makes them: the window on a built-in sample with
// one viewport, then Ctrl+4 (the View menu's action), and from that moment a click on the new
// viewports every --interval ms, posted from another thread as the window system posts them, each
// stamped with the time it was made. For each click it prints how long it waited before its view
// received it (the time of delivery minus the event's timestamp), and before the window had
// drawn again after it (the view shown active: the end of the window's next update): what an
// artist feels as a click that does not register. Needs a display (Xvfb will do) and GL 4.3.
//
//   parallax-bench-studio-clicks [--views 2|4] [--clicks N] [--interval MS] [--size WxH]
//                                [--sample-size N] [--slow-events MS]

#include "StudioBenchSupport.h"
#include "preview/FramePacer.h"
#include "preview/GlSupport.h"
#include "preview/PreviewWidget.h"
#include "preview/Viewport.h"
#include "preview/ViewportGrid.h"
#include "window/MainWindow.h"

#include <QAction>
#include <QMouseEvent>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using namespace px;
using namespace px::studio;
using namespace px::studio::bench;

int main(int argc, char** argv) {
    setUpOpenGl();
    TracingApplication app(argc, argv);
    int views = 4, clicks = 20, intervalMs = 100, sampleSize = 512;
    QSize size(1600, 1000);
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i], value = argv[i + 1];
        if (flag == "--views")
            views = std::stoi(value);
        else if (flag == "--clicks")
            clicks = std::stoi(value);
        else if (flag == "--interval")
            intervalMs = std::stoi(value);
        else if (flag == "--sample-size")
            sampleSize = std::stoi(value);
        else if (flag == "--slow-events")
            app.slowMs = std::stoi(value);
        else if (flag == "--size")
            size = QSize(std::stoi(value), std::stoi(value.substr(value.find('x') + 1)));
    }
    if ((views != 2 && views != 4) || clicks < 1 || intervalMs < 1 || sampleSize < 16) {
        std::fprintf(stderr, "usage: parallax-bench-studio-clicks [--views 2|4] [--clicks N] "
                             "[--interval MS] [--size WxH] [--sample-size N] [--slow-events MS]\n");
        return 2;
    }
    const GlProbe& gl = probeOpenGl();
    if (!gl.usable) {
        std::fprintf(stderr, "parallax-bench-studio-clicks: no GL 4.3 (%s)\n",
                     gl.reason.toUtf8().constData());
        return 1;
    }
    app.since.start();
    MainWindow window(gl.reason);
    window.setInteractive(false);
    window.newSample(ProceduralMap::Bricks, sampleSize);
    window.viewports()->setLayoutCount(1);
    window.resize(size);
    window.show();
    PreviewWidget* first = window.viewports()->viewport(0)->preview();
    if (!waitUntil([&] { return first->framesRendered() > 0 && first->stats().valid; }, 300000)) {
        std::fprintf(stderr, "parallax-bench-studio-clicks: the first view did not draw\n");
        return 1;
    }
    QAction* layout = nullptr;
    for (QAction* a : window.findChildren<QAction*>())
        if (a->shortcut() ==
            QKeySequence(QKeyCombination(Qt::ControlModifier, Qt::Key(Qt::Key_0 + views))))
            layout = a;
    if (!layout) {
        std::fprintf(stderr, "parallax-bench-studio-clicks: no Ctrl+%d action\n", views);
        return 1;
    }

    // Each click's wait: delivery time minus its timestamp (both on app.since's clock), and the
    // end of the window's first update after its delivery minus its timestamp.
    std::mutex mutex;
    struct Click {
        qint64 made = 0, delivered = -1, shown = -1;
    };
    std::vector<Click> waits;
    const QObject* windowHandle = nullptr;
    app.observe = [&](QObject* receiver, QEvent* event) {
        if (event->type() != QEvent::MouseButtonPress || !qobject_cast<PreviewWidget*>(receiver))
            return;
        const auto* press = static_cast<const QMouseEvent*>(event);
        std::lock_guard lock(mutex);
        waits.push_back({static_cast<qint64>(press->timestamp()), app.since.elapsed(), -1});
    };
    app.handled = [&](const QObject* receiver, int type) {
        if (type != QEvent::UpdateRequest || receiver != windowHandle)
            return;
        std::lock_guard lock(mutex);
        for (Click& c : waits)
            if (c.shown < 0)
                c.shown = app.since.elapsed();
    };
    windowHandle = &window; // the window's update paints every widget in it
    std::vector<PreviewWidget*> targets;
    for (int i = 1; i < views; ++i)
        targets.push_back(window.viewports()->viewport(i)->preview());

    const qint64 switched = app.since.elapsed();
    if (app.slowMs > 0)
        std::fprintf(stderr, "-- layout change at %.3f s\n", switched / 1000.0);
    FramePacer::noteInput(); // the key press of Ctrl+4, which the action stands for here
    layout->trigger();       // the new viewports show, and draw from the next turn on
    std::thread clicker([&] {
        for (int i = 0; i < clicks; ++i) {
            const auto due = std::chrono::milliseconds(switched + qint64(i) * intervalMs);
            while (std::chrono::milliseconds(app.since.elapsed()) < due)
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            PreviewWidget* target = targets[static_cast<std::size_t>(i) % targets.size()];
            const QPointF at(20.0, 20.0);
            for (QEvent::Type type : {QEvent::MouseButtonPress, QEvent::MouseButtonRelease}) {
                auto* e = new QMouseEvent(type, at, at, Qt::LeftButton,
                                          type == QEvent::MouseButtonPress ? Qt::LeftButton
                                                                           : Qt::NoButton,
                                          Qt::NoModifier);
                e->setTimestamp(static_cast<quint64>(app.since.elapsed()));
                QCoreApplication::postEvent(target, e);
            }
        }
    });
    const bool received = waitUntil(
        [&] {
            std::lock_guard lock(mutex);
            return int(waits.size()) >= clicks && waits.back().shown >= 0;
        },
        600000);
    clicker.join();
    // Every view drawn and measured: what the layout change costs in all.
    const bool settled = waitUntil(
        [&] {
            return std::all_of(targets.begin(), targets.end(), [](PreviewWidget* p) {
                return p->framesRendered() > 0 && p->stats().valid;
            });
        },
        600000);
    const qint64 settledMs = app.since.elapsed() - switched;
    if (!received || !settled) {
        std::fprintf(stderr, "parallax-bench-studio-clicks: %s\n",
                     received ? "the new views did not draw" : "the clicks did not arrive");
        return 1;
    }
    std::printf("editor, bricks %d², 1 -> %d viewports at %dx%d, %s\n", sampleSize, views,
                size.width(), size.height(), gl.renderer.toUtf8().constData());
    std::printf("clicks every %d ms from the layout change; each one's wait for its view:\n",
                intervalMs);
    std::vector<qint64> delivered, shown;
    for (std::size_t i = 0; i < waits.size(); ++i) {
        const Click& c = waits[i];
        std::printf("  click %2zu at %5lld ms: delivered after %4lld ms, shown after %4lld ms\n",
                    i + 1, static_cast<long long>(c.made - switched),
                    static_cast<long long>(c.delivered - c.made),
                    static_cast<long long>(c.shown - c.made));
        delivered.push_back(c.delivered - c.made);
        shown.push_back(c.shown - c.made);
    }
    std::sort(delivered.begin(), delivered.end());
    std::sort(shown.begin(), shown.end());
    std::printf("delivered: longest %lld ms, median %lld ms; shown: longest %lld ms, median %lld "
                "ms; every new view drawn and measured %lld ms after the change\n",
                static_cast<long long>(delivered.back()),
                static_cast<long long>(delivered[delivered.size() / 2]),
                static_cast<long long>(shown.back()),
                static_cast<long long>(shown[shown.size() / 2]), static_cast<long long>(settledMs));
    return 0;
}

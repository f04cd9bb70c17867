#pragma once
// What the editor's scenario benchmarks share: an application that names every slow event (and,
// asked, every resize), and a wait that sleeps on the event loop as the editor does.

#include <QApplication>
#include <QElapsedTimer>
#include <QMetaEnum>
#include <QResizeEvent>
#include <QTimer>
#include <cstdio>
#include <functional>

namespace px::studio::bench {

// With slowMs > 0: every event whose handling took longer is printed (receiver, type, ms): where
// the event loop's gaps come from. `observe` sees every event before it is handled, `handled`
// each event's type and receiver after (the receiver may be gone: compare, never dereference).
class TracingApplication : public QApplication {
public:
    using QApplication::QApplication;
    qint64 slowMs = 0;
    bool traceResizes = false; // every widget's resize, to find what re-lays out the views
    QElapsedTimer since;       // started in main
    std::function<void(QObject*, QEvent*)> observe;
    std::function<void(const QObject*, int)> handled;
    static QByteArray typeName(int type) {
        const char* key = QMetaEnum::fromType<QEvent::Type>().valueToKey(type);
        return key ? QByteArray(key) : "type " + QByteArray::number(type);
    }
    bool notify(QObject* receiver, QEvent* event) override {
        if (observe)
            observe(receiver, event);
        if (slowMs <= 0 && !traceResizes) {
            const int type = event->type();
            const bool result = QApplication::notify(receiver, event);
            if (handled)
                handled(receiver, type);
            return result;
        }
        // Named before the event: its handling may delete the receiver.
        const int type = event->type();
        const QObject* parent = receiver->parent();
        const QByteArray name = QByteArray(receiver->metaObject()->className()) + " '" +
                                receiver->objectName().toUtf8() + "' (parent " +
                                (parent ? parent->metaObject()->className() : "-") + ")";
        const qint64 start = since.elapsed();
        if (traceResizes && type == QEvent::Resize) {
            const auto* r = static_cast<const QResizeEvent*>(event);
            std::fprintf(stderr, "resize at %.3f s: %s %dx%d -> %dx%d\n", start / 1000.0,
                         name.constData(), r->oldSize().width(), r->oldSize().height(),
                         r->size().width(), r->size().height());
        }
        const bool result = QApplication::notify(receiver, event);
        if (handled)
            handled(receiver, type);
        if (const qint64 ms = since.elapsed() - start; slowMs > 0 && ms >= slowMs)
            std::fprintf(stderr, "slow event at %.3f s (monotonic %.3f): %lld ms, %s, %s\n",
                         start / 1000.0, (since.msecsSinceReference() + start) / 1000.0,
                         static_cast<long long>(ms), typeName(type).constData(), name.constData());
        return result;
    }
};

// Runs the event loop until `done` (asked at least every 20 ms) or the timeout; false on timeout.
inline bool waitUntil(const std::function<bool()>& done, int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    QTimer wake; // `done` is asked again at least this often
    wake.start(20);
    while (!done()) {
        if (clock.elapsed() > timeoutMs)
            return false;
        // Sleeps until an event comes, as the editor's own loop does: spinning took one of the
        // two cores from the bakes and llvmpipe.
        QCoreApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents);
    }
    return true;
}

} // namespace px::studio::bench

#include "jobs/BackgroundLoad.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QProgressDialog>
#include <QTimer>
#include <algorithm>

namespace px::studio {

namespace {
int quietMs = 300; // a load this short shows no dialog
}

void setBusyDialogDelay(int ms) {
    quietMs = std::max(0, ms);
}

bool waitForWork(QWidget* window, const QString& label, QFutureWatcherBase& watcher,
                 const std::atomic<float>* progress) {
    QEventLoop loop;
    QObject::connect(&watcher, &QFutureWatcherBase::finished, &loop, &QEventLoop::quit);
    if (watcher.isFinished())
        return false;
    // First a quiet moment: paint, but hold user input (nothing may edit the document the load
    // will replace).
    QTimer::singleShot(quietMs, &loop, &QEventLoop::quit);
    loop.exec(QEventLoop::ExcludeUserInputEvents);
    if (watcher.isFinished())
        return false;

    QProgressDialog dialog(window);
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setWindowTitle(QObject::tr("Working"));
    dialog.setRange(0, progress ? 100 : 0); // busy where the work reports no progress
    dialog.setAutoReset(false);             // a full bar must not close it: the work may go on
    dialog.setAutoClose(false);
    dialog.setMinimumDuration(0);
    QElapsedTimer clock;
    clock.start();
    auto showTime = [&] {
        dialog.setLabelText(
            QObject::tr("%1 %2 s").arg(label).arg((clock.elapsed() + quietMs) / 1000.0, 0, 'f', 1));
        if (progress)
            dialog.setValue(static_cast<int>(100.0f * progress->load()));
    };
    showTime();
    QTimer tick;
    QObject::connect(&tick, &QTimer::timeout, &dialog, showTime);
    tick.start(100);
    bool cancelled = false;
    QObject::connect(&dialog, &QProgressDialog::canceled, &loop, [&] {
        cancelled = true;
        loop.quit();
    });
    dialog.show();
    if (!watcher.isFinished())
        loop.exec();
    return cancelled && !watcher.isFinished();
}

} // namespace px::studio

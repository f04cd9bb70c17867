#pragma once
// Reading and decoding maps off the GUI thread. An 8192² map takes seconds to decode; done on the
// GUI thread it froze the window (no repaint) for all of them. `loadInBackground` runs the load on
// a worker while the window keeps painting and, past a moment, shows a window-modal busy dialog
// naming the file with the time so far and a Cancel button; before it shows, user input waits.
// The caller gets the result as if the load had been synchronous; Cancel returns a cancelled
// error at once and the load's result is dropped when it arrives.

#include "parallax/Result.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QtConcurrent/QtConcurrentRun>
#include <atomic>
#include <functional>

class QWidget;

namespace px::studio {

// How long work runs before the dialog shows (300 ms: a shorter load shows none). Tests set 0 to
// see the dialog of any load.
void setBusyDialogDelay(int ms);

// Spins the GUI thread's events until `watcher` finishes or Cancel is pressed (returns true);
// the dialog says `label` ("Loading bricks.png…") and the seconds so far, and fills its bar from
// `progress` (0 to 1, written by the work) where there is one.
bool waitForWork(QWidget* window, const QString& label, QFutureWatcherBase& watcher,
                 const std::atomic<float>* progress = nullptr);

// Any such work (the editor's Auto measurement too); Cancel gives a cancelled error.
template <typename T>
Result<T> runInBackground(QWidget* window, const QString& label, std::function<Result<T>()> work,
                          const std::atomic<float>* progress = nullptr) {
    QFutureWatcher<Result<T>> watcher;
    watcher.setFuture(QtConcurrent::run(std::move(work)));
    if (waitForWork(window, label, watcher, progress))
        return Error{label.toStdString() + " cancelled", ErrorKind::Cancelled, {}};
    return watcher.result();
}

// `what`: the file's name, or what is loaded ("3 maps").
template <typename T>
Result<T> loadInBackground(QWidget* window, const QString& what, std::function<Result<T>()> work) {
    return runInBackground<T>(window, QObject::tr("Loading %1…").arg(what), std::move(work));
}

} // namespace px::studio

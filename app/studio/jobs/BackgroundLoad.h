#pragma once
// Reading and decoding maps off the GUI thread. An 8192² map takes seconds to decode; done on the
// GUI thread it froze the window (no repaint) for all of them. `loadInBackground` runs the load on
// a worker while the window keeps painting and, past a moment, shows a window-modal busy dialog
// naming the file with the time so far and a Cancel button; before it shows, user input waits.
// The caller gets the result as if the load had been synchronous; Cancel returns a cancelled
// error at once and the load's result is dropped when it arrives.

#include "parallax/Result.h"

#include <QFutureWatcher>
#include <QString>
#include <QtConcurrent/QtConcurrentRun>
#include <functional>

class QWidget;

namespace px::studio {

// Spins the GUI thread's events until `watcher` finishes or Cancel is pressed (returns true).
bool waitForLoad(QWidget* window, const QString& what, QFutureWatcherBase& watcher);

template <typename T>
Result<T> loadInBackground(QWidget* window, const QString& what, std::function<Result<T>()> work) {
    QFutureWatcher<Result<T>> watcher;
    watcher.setFuture(QtConcurrent::run(std::move(work)));
    if (waitForLoad(window, what, watcher))
        return Error{"loading " + what.toStdString() + " was cancelled", ErrorKind::Cancelled, {}};
    return watcher.result();
}

} // namespace px::studio

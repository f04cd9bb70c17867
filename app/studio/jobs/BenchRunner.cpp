#include "jobs/BenchRunner.h"

#include <QMetaObject>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>
#include <chrono>

namespace px::studio {

BenchRunner::BenchRunner(QObject* parent) : QObject(parent) {
    connect(&m_watcher, &QFutureWatcher<BenchOutcome>::finished, this, [this] {
        m_running = false;
        emit finished(m_watcher.result());
    });
}

BenchRunner::~BenchRunner() {
    if (m_cancel)
        m_cancel->store(true);
    m_watcher.waitForFinished();
}

void BenchRunner::cancel() {
    if (m_cancel)
        m_cancel->store(true);
}

void BenchRunner::start(BenchConfig config) {
    if (m_running)
        return;
    m_running = true;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    emit started();
    QPointer<BenchRunner> self(this);
    EvalControl control;
    control.cancel = m_cancel.get();
    control.progress = [self](const EvalProgress& p) {
        const int done = p.done, total = p.total;
        const QString stage = QString::fromStdString(p.stage);
        QMetaObject::invokeMethod(
            self.data(),
            [self, done, total, stage] {
                if (self)
                    emit self->progress(done, total, stage);
            },
            Qt::QueuedConnection);
    };
    std::shared_ptr<std::atomic<bool>> flag = m_cancel;
    m_watcher.setFuture(QtConcurrent::run([config = std::move(config), control, flag]() mutable {
        BenchOutcome outcome;
        const auto start = std::chrono::steady_clock::now();
        Result<BenchReport> report = runBench(config, control);
        // A GPU timer holds a GL context current on this thread: it must end here, not on the
        // thread that happens to destroy this task.
        config.gpuTimer = nullptr;
        if (report)
            outcome.report = std::move(*report);
        else if (isEvaluationCancelled(report.error()))
            outcome.cancelled = true;
        else
            outcome.error = QString::fromStdString(report.error().message);
        outcome.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return outcome;
    }));
}

} // namespace px::studio

#pragma once
// Runs the bench (error against cost of every technique, core/eval) on a worker thread with
// progress and cancellation; the report comes back on the GUI thread.

#include "parallax/eval/Bench.h"

#include <QFutureWatcher>
#include <QObject>
#include <atomic>
#include <memory>

namespace px::studio {

struct BenchOutcome {
    std::optional<BenchReport> report;
    QString error; // empty on success or cancellation
    bool cancelled = false;
    double seconds = 0.0;
};

class BenchRunner : public QObject {
    Q_OBJECT
public:
    explicit BenchRunner(QObject* parent = nullptr);
    ~BenchRunner() override; // cancels and waits

    bool isRunning() const { return m_running; }
    void start(BenchConfig config); // ignored while running
    void cancel();

signals:
    void started();
    void progress(int done, int total, const QString& stage);
    void finished(const px::studio::BenchOutcome& outcome);

private:
    bool m_running = false;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    QFutureWatcher<BenchOutcome> m_watcher;
};

} // namespace px::studio

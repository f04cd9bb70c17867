#pragma once
// Progress reporting and cooperative cancellation for the evaluations (bench, stability suite), in
// the same shape as the bakers' BakeControl, so the editor can run both on a worker thread with
// one cancel flag:
//
//   std::atomic<bool> stop{false};
//   EvalControl control{[](const EvalProgress& p) { /* post p to the UI */ }, &stop};
//   Result<BenchReport> report = runBench(config, control); // on a worker thread
//   if (!report && isEvaluationCancelled(report.error())) { /* stopped: nothing was produced */ }

#include "parallax/Result.h"

#include <atomic>
#include <functional>
#include <string>

namespace px {

struct EvalProgress {
    int done = 0;      // units of work finished
    int total = 0;     // units of work in all, fixed before the first call
    std::string stage; // what just finished, for people ("pom layers 8-32, bricks.png, polar 80")
};

struct EvalControl {
    // Called after each unit of work on the thread that runs the evaluation (never concurrently,
    // never from its worker threads; recommend()'s bakes excepted, see there); keep it short:
    // post, don't paint.
    std::function<void(const EvalProgress&)> progress;
    // Polled between rows of rays; once it reads true the evaluation returns
    // evaluationCancelled() within about one row of one trace (or one bake). Null: never.
    const std::atomic<bool>* cancel = nullptr;

    bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
};

// The error a cancelled evaluation returns ("the evaluation was cancelled").
Error evaluationCancelled();
bool isEvaluationCancelled(const Error& error);

} // namespace px

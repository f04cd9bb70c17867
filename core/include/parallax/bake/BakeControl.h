#pragma once
// Progress reporting and cooperative cancellation for long bakes: what the command line's progress
// line and Ctrl-C, and the editor's background bakes, hand to every baker.
//
//   std::atomic<bool> stop{false};
//   BakeControl control{[](float done) { /* post to the UI */ }, &stop};
//   Result<ConeMap> cones = bakeConeMap(field, wrap, ConeKind::Relaxed, control);
//   if (!cones && isCancelled(cones.error())) { /* the user stopped it: nothing was produced */ }

#include "parallax/Result.h"

#include <atomic>
#include <functional>

namespace px {

struct BakeControl {
    // Called with the fraction done in [0, 1], non-decreasing, ending with 1 on success. It may be
    // called on a worker thread, but never concurrently; keep it short (post, don't paint).
    std::function<void(float)> progress;
    // Polled often (every few milliseconds of work). Once it reads true the bake stops, discards
    // what it has done and returns cancelledError(). Null: never cancelled.
    const std::atomic<bool>* cancel = nullptr;

    bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
};

// The error every baker returns when it was cancelled ("the bake was cancelled").
Error cancelledError();
bool isCancelled(const Error& error);

} // namespace px

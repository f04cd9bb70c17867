#pragma once
// Tracing the canonical scene's rays for the evaluations, cancellable, optionally timed on one
// thread (the CPU cost the bench reports is that of one core: comparable across machines and
// free of scheduling noise from other threads).

#include "parallax/trace/TraceScene.h"

#include <atomic>
#include <optional>
#include <vector>

namespace px {

enum class RayTiming { Parallel, OneThread };

// Traces every ray of `scene` (row-major, like traceScene) into `hits`. Returns the elapsed
// steady-clock nanoseconds of the trace (OneThread; 0 for Parallel), or nothing once a stop is
// requested through `cancel` (polled before each row; may be null).
std::optional<double> traceBatch(const Tracer& tracer, const TraceScene& scene, RayTiming timing,
                                 std::vector<TraceResult>& hits, const std::atomic<bool>* cancel);

} // namespace px

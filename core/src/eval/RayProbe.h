#pragma once
// The rays a recommendation measures: per polar angle, raysPerSide^2 stratified, jittered origins
// for each azimuth, from a fixed seed (the same input always draws the same rays, and every
// setting sees the same rays: comparisons between settings are not blurred by sampling).

#include "parallax/eval/Recommendation.h"
#include "parallax/trace/Tracer.h"

#include <atomic>
#include <functional>
#include <glm/vec2.hpp>
#include <optional>
#include <span>
#include <vector>

namespace px {

struct RaySample {
    double polarDeg = 0.0;
    std::vector<glm::dvec2> uv0;
    std::vector<glm::vec2> P; // uv offset per unit of normalised depth
};

// Which offset the rays take: the true relief's s tan(polar) (docs/conventions.md §5), or an
// engine's model of it (Godot offsets by the normalised view vector: s sin(polar)).
enum class RayModel { Relief, NormalisedView };

RaySample sampleRays(int raysPerSide, double polarDeg, std::span<const double> azimuthDeg,
                     float scale, RayModel model);

// Traces rays [begin, end) of a sample into `hits`; called from several threads at once on
// disjoint ranges, so per-thread state (a Sampler) belongs inside.
using RangeTrace = std::function<void(const RaySample& rays, std::size_t begin, std::size_t end,
                                      std::span<TraceResult> hits)>;

RangeTrace tracerRange(const Tracer& tracer);

// Every ray, in parallel; nothing once `cancel` reads true.
std::optional<std::vector<TraceResult>> traceSample(const RaySample& rays, const RangeTrace& trace,
                                                    const std::atomic<bool>* cancel);

// The same, but it gives up (nothing returned, `fetchesAtLeast` over the limit) as soon as the
// rays traced so far have made more than maxMeanFetches x (all the rays) fetches: the mean over
// all of them can only be higher, and fetchesAtLeast is a lower bound of it. Whether it gives up
// does not depend on the order the blocks ran in: it does exactly when the whole sample's sum is
// over the limit.
std::optional<std::vector<TraceResult>>
traceSampleWithin(const RaySample& rays, const RangeTrace& trace, const std::atomic<bool>* cancel,
                  double maxMeanFetches, double& fetchesAtLeast);

// Nanoseconds per ray on one thread (the fastest of two passes over the sample).
double timeSample(const RaySample& rays, const RangeTrace& trace);

// The figures of one angle against the exact hits of the same rays (meets left false).
AngleMeasure measureAngle(const RaySample& rays, std::span<const TraceResult> hits,
                          std::span<const TraceResult> reference, int width, int height,
                          double confidence);

// Whether an angle's figures meet a budget: the p99's upper bound, the sample's maximum, or the
// bound and no ray on another surface.
bool meetsBudget(const AngleMeasure& m, const ErrorBudget& budget);

} // namespace px

#pragma once
// The bakers' side of BakeControl: counts work done by parallel loops, reports progress in
// steps, and tells the loops when to stop.

#include "parallax/bake/BakeControl.h"

#include <atomic>
#include <cstdint>
#include <mutex>

namespace px {

class BakeProgress {
public:
    BakeProgress(const BakeControl& control, std::int64_t totalWork);

    // Records `work` units done (thread-safe). Returns false once the bake should stop.
    bool advance(std::int64_t work);
    bool stopRequested() const { return m_control.cancelled(); }
    // Reports 1.0 if it has not been reported yet (call once the result is complete).
    void finish();

private:
    static constexpr int kSteps = 200;
    const BakeControl& m_control;
    const std::int64_t m_total;
    std::atomic<std::int64_t> m_done{0};
    std::atomic<int> m_reported{0};
    std::mutex m_mutex;
};

} // namespace px

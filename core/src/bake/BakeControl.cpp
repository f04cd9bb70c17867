#include "parallax/bake/BakeControl.h"

#include "bake/BakeProgress.h"

#include <algorithm>

namespace px {

namespace {
constexpr const char* kCancelled = "the bake was cancelled";
}

Error cancelledError() {
    return Error{kCancelled, ErrorKind::Cancelled, {}};
}

bool isCancelled(const Error& error) {
    return error.cancelled();
}

BakeProgress::BakeProgress(const BakeControl& control, std::int64_t totalWork)
    : m_control(control), m_total(std::max<std::int64_t>(totalWork, 1)) {}

bool BakeProgress::advance(std::int64_t work) {
    const std::int64_t done = m_done.fetch_add(work, std::memory_order_relaxed) + work;
    if (m_control.progress) {
        // Report in steps of 1/kSteps; a thread that cannot take the lock skips its report rather
        // than wait (the next one catches up).
        const int step = static_cast<int>(std::min<std::int64_t>(done * kSteps / m_total, kSteps));
        if (step > m_reported.load(std::memory_order_relaxed)) {
            std::unique_lock lock(m_mutex, std::try_to_lock);
            if (lock.owns_lock() && step > m_reported.load(std::memory_order_relaxed)) {
                m_reported.store(step, std::memory_order_relaxed);
                m_control.progress(static_cast<float>(step) / kSteps);
            }
        }
    }
    return !m_control.cancelled();
}

void BakeProgress::finish() {
    if (!m_control.progress)
        return;
    std::lock_guard lock(m_mutex);
    if (m_reported.load(std::memory_order_relaxed) < kSteps) {
        m_reported.store(kSteps, std::memory_order_relaxed);
        m_control.progress(1.0f);
    }
}

} // namespace px

#include "ArenaProbe.h"

#include <chrono>
#include <functional>
#include <mutex>
#include <tbb/parallel_for.h>
#include <thread>
#include <unistd.h>

namespace px::studio::test {

namespace {

template <typename Run> std::map<int, int> threadNices(Run run) {
    std::mutex mutex;
    std::map<int, int> seen;
    // Until a worker has joined the caller (a lowered worker on a busy machine may take a while
    // to be scheduled), each iteration leaves room to steal; then the rest run through.
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::seconds(std::thread::hardware_concurrency() > 1 ? 30 : 0);
    run([&] {
        tbb::parallel_for(0, 1 << 16, [&](int) {
            bool joined = false;
            {
                const std::lock_guard lock(mutex);
                seen[static_cast<int>(gettid())] = thisThreadsNice();
                joined = seen.size() >= 2;
            }
            if (!joined && std::chrono::steady_clock::now() < deadline)
                std::this_thread::sleep_for(std::chrono::microseconds(500)); // room to steal
        });
    });
    return seen;
}

} // namespace

std::map<int, int> threadNicesInLoop(BackgroundArena& arena) {
    return threadNices([&](const std::function<void()>& loop) { arena.execute(loop); });
}

std::map<int, int> threadNicesInDefaultLoop() {
    return threadNices([](const std::function<void()>& loop) { loop(); });
}

} // namespace px::studio::test

#include "ArenaProbe.h"

#include <chrono>
#include <mutex>
#include <tbb/parallel_for.h>
#include <thread>
#include <unistd.h>

namespace px::studio::test {

std::map<int, int> threadNicesInLoop(BackgroundArena& arena) {
    std::mutex mutex;
    std::map<int, int> seen;
    arena.execute([&] {
        tbb::parallel_for(0, 256, [&](int) {
            {
                const std::lock_guard lock(mutex);
                seen[static_cast<int>(gettid())] = thisThreadsNice();
            }
            std::this_thread::sleep_for(std::chrono::microseconds(500)); // room to steal
        });
    });
    return seen;
}

} // namespace px::studio::test

#pragma once
// Background work (bakes, and the TBB workers they fan out to) runs at a lower CPU priority than
// the GUI thread and the GL driver's threads: on a 2-core machine a bake on every core otherwise
// starves the event loop (llvmpipe, 8192² cone bake: a progress update took 60 ms, a frame 300).
// Only threads doing that work are lowered: a thread cannot raise its priority again without
// privileges, and the threads that run loads and exports (Qt's global pool, TBB's default arena)
// must not inherit a bake's priority.

#include <functional>
#include <memory>

namespace px::studio {

// The nice value background threads run at (Linux; elsewhere nothing changes).
inline constexpr int kBackgroundNice = 10;

// Lowers the calling thread's priority alone, for good: call it only on a thread that does
// background work from then on (a pool of its own: BakeRunner's, MapUpload's).
void lowerThisThreadsPriority();

// A TBB arena whose worker threads run at kBackgroundNice while they work in it, and at their own
// priority again once they leave it. TBB's workers are shared by every arena, so a worker is
// lowered only where the system lets it rise again (root, CAP_SYS_NICE, or an RLIMIT_NICE
// allowing it): for an ordinary user (RLIMIT_NICE 0) a lowered worker would stay at
// kBackgroundNice and run every later job of the default arena (an environment's prefilter, the
// bench, exports) at background priority. There the workers keep their priority, and only the
// bake's own thread (lowerThisThreadsPriority) runs lower. The thread that calls execute() keeps
// its own priority.
class BackgroundArena {
public:
    BackgroundArena();
    ~BackgroundArena();
    BackgroundArena(const BackgroundArena&) = delete;
    BackgroundArena& operator=(const BackgroundArena&) = delete;

    // Runs `work` in the arena (its parallel loops run on the arena's workers); blocks.
    void execute(const std::function<void()>& work);
    // Whether the workers are lowered while they work here (see above).
    bool lowersWorkers() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// The calling thread's nice value (0 where there is none), and a TBB worker's in the default arena
// (tests).
int thisThreadsNice();
int tbbWorkerNice();
// Whether this process may raise a thread's priority again (tests: a worker then leaves the
// background arena at its own priority).
bool canRaisePriority();

} // namespace px::studio

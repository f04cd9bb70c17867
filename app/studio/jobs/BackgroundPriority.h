#pragma once
// Background work (bakes, and the TBB workers they fan out to) runs at a lower CPU priority than
// the GUI thread and the GL driver's threads: on a 2-core machine a bake on every core otherwise
// starves the event loop (llvmpipe, 8192² cone bake: a progress update took 60 ms, a frame 300).

namespace px::studio {

// The nice value background threads run at (Linux; elsewhere nothing changes).
inline constexpr int kBackgroundNice = 10;

// Lowers the calling thread's priority alone. Without privileges it cannot be raised again: call
// it only on threads that do background work from then on (pool threads, bake jobs).
void lowerThisThreadsPriority();

// From now on TBB's worker threads lower their own priority as they join the default arena; the
// thread that starts a parallel loop keeps its own (the GUI thread stays as it is).
void lowerTbbWorkersPriority();

// The calling thread's nice value (0 where there is none), and a TBB worker's (tests).
int thisThreadsNice();
int tbbWorkerNice();

} // namespace px::studio

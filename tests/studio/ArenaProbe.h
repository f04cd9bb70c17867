#pragma once
// A parallel loop in a BackgroundArena, seen from inside: each thread that ran it and its nice
// value there. Apart from the test, which includes Qt: TBB's headers and Qt's `emit` collide.

#include "jobs/BackgroundPriority.h"

#include <map>

namespace px::studio::test {

std::map<int, int> threadNicesInLoop(BackgroundArena& arena); // thread id -> nice value
// The same in TBB's default arena, where loads, exports and the bench run.
std::map<int, int> threadNicesInDefaultLoop();

} // namespace px::studio::test

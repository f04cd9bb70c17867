#pragma once
// A parallel loop in a BackgroundArena, seen from inside: each thread that ran it and its nice
// value there. Apart from the test, which includes Qt: TBB's headers and Qt's `emit` collide.

#include "jobs/BackgroundPriority.h"

#include <map>

namespace px::studio::test {

std::map<int, int> threadNicesInLoop(BackgroundArena& arena); // thread id -> nice value

} // namespace px::studio::test

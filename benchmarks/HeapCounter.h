#pragma once
// Counts the bytes live on the heap (every operator new of the process), so a benchmark can report
// the peak a bake adds on top of what was allocated before it started.

#include <cstddef>

namespace px::bench {

std::size_t heapInUse();
// Restarts the peak at the current use; heapPeak() - that is what was added since.
void resetHeapPeak();
std::size_t heapPeak();

} // namespace px::bench

#pragma once
// CPU seconds of the whole process (every thread): on a shared machine, this divided by the cores
// is what the wall time would be with the cores to itself.

#include <sys/resource.h>

namespace px::bench {

inline double processCpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

} // namespace px::bench

#pragma once
// The temporary files and folders a run has open, so that an interrupted run removes them, and the
// recognition of those a killed run (SIGKILL, power loss) left behind, so that the next run on the
// same target removes them.
//
// Temporary names all have the form ".NAME.<role><pid>-<n>" beside the target NAME, role one of
// "tmp", "export-tmp", "export-old"; a leftover is one whose pid is no longer running.

#include <filesystem>

namespace px {

// Records a temporary path (a file, or a folder registered before the files in it). Returns a
// handle for releaseTemporary(); -1 when the table is full (the path is then only removed by the
// next run's sweep).
int registerTemporary(const std::filesystem::path& path);
void releaseTemporary(int handle);

// Removes every registered temporary, newest first (files, then their folder). Async-signal-safe:
// only unlink() and rmdir(), for the CLI's SIGINT/SIGTERM handler.
void removeTemporariesNow() noexcept;

// Removes the leftovers of dead runs beside `target` (see above). Returns how many it removed.
int removeStaleTemporaries(const std::filesystem::path& target);

// Within an InterruptDeferral (a few renames that must all happen), the CLI's signal handler only
// records the signal: deferInterrupt() returns true and the signal is raised again when the last
// deferral ends. Async-signal-safe.
bool deferInterrupt(int signal) noexcept;
class InterruptDeferral {
public:
    InterruptDeferral();
    ~InterruptDeferral();
    InterruptDeferral(const InterruptDeferral&) = delete;
    InterruptDeferral& operator=(const InterruptDeferral&) = delete;
};

// Test hook for the fault suite: with PX_TEST_RAISE=SIGNAL:POINT (SIGNAL one of INT, TERM, KILL)
// the process raises that signal the first time it reaches `point`, so that interruptions land at
// exact moments without timing. Points: "write" (half a file written to its temporary), "commit"
// (before the rename), "export-commit" (every file staged), "export-update" (half an earlier export
// updated in place).
void testInterruptPoint(const char* point);

// Registers a path for its lifetime.
class TemporaryGuard {
public:
    explicit TemporaryGuard(const std::filesystem::path& path)
        : m_handle(registerTemporary(path)) {}
    ~TemporaryGuard() { releaseTemporary(m_handle); }
    TemporaryGuard(const TemporaryGuard&) = delete;
    TemporaryGuard& operator=(const TemporaryGuard&) = delete;

private:
    int m_handle;
};

} // namespace px

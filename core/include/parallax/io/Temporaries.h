#pragma once
// The temporary files and folders a run has open, so that an interrupted run removes them, and the
// recognition of those a killed run (SIGKILL, power loss) left behind, so that the next run on the
// same target removes them.
//
// Temporary names all have the form ".NAME.<role><pid>-<n>.<host>" beside the target NAME, role
// one of "tmp", "export-tmp", "set-tmp" (and "export-old" of older versions), <host> eight hex
// digits naming the boot and the PID namespace of the writer. A pid means something only on its
// own host: a writer in another container sharing the folder may have any pid. So every writer
// holds an flock() on its temporary (file or folder) from creation until it is renamed or
// removed, and a leftover is removed only when that lock is free and either its host is ours and
// its pid is gone, or it has not changed for an hour (a writer whose file system has no locks).
// A set stage that was already committing (StagedSet.h) is finished, not removed.

#include <filesystem>
#include <string>
#include <string_view>

namespace px {

// A hidden name beside `target` for this run's temporary of `role` (see above), unique to this
// process and call.
std::filesystem::path temporarySibling(const std::filesystem::path& target, std::string_view role);

// Takes a shared flock() on `fd`, the writer's sign of life on its temporary (see above).
void holdTemporary(int fd);

// This host's token: the boot and the PID namespace, as eight hex digits.
const std::string& hostToken();

// Records a temporary path (a file, or a folder registered before the files in it). Returns a
// handle for releaseTemporary(); -1 when the table is full (the path is then only removed by the
// next run's sweep).
int registerTemporary(const std::filesystem::path& path);
void releaseTemporary(int handle);

// Removes every registered temporary, newest first (files, then their folder). Async-signal-safe:
// only unlink() and rmdir(), for the CLI's SIGINT/SIGTERM handler.
void removeTemporariesNow() noexcept;

// Removes the leftovers of dead runs beside `target` (see above), and finishes their committed set
// stages. Returns how many it removed or finished.
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

// Test hook for the fault suite: with PX_TEST_RAISE=SIGNAL:POINT (SIGNAL one of INT, TERM, KILL,
// STOP) the process raises that signal the first time it reaches `point`, so that interruptions
// land at exact moments without timing (STOP: the test continues the process when it has done what
// it wanted to do meanwhile). Points: "write" (half a file written to its temporary), "commit"
// (before the rename), "export-commit" (every file staged), "export-update" (half an earlier export
// updated in place), "frames-commit" and "frames-update" (the same for a turntable's frames).
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

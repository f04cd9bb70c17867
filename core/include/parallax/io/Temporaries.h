#pragma once
// The temporary files and stage folders of a run: their names, their removal on Ctrl-C, and the
// removal of those a killed run (SIGKILL, power loss) left behind.
//
// Names: ".px-<kind>-<H>-<R>" beside (or, for a stage, inside) the target, kind "tmp" (a file) or
// "stage" (a folder of regular files), H sixteen hex digits hashing the target's name, R sixteen
// random ones: 43 bytes whatever the target's name, so any legal name has its temporaries. A
// writer holds an flock() on its temporary from creation until it is renamed or removed.
//
// Nothing found on disk is obeyed: a leftover is only ever removed, and only when it is provably a
// dead writer's of the same kind: its name, its owner (this user), its type (a stage holds only
// regular files with one link), and its lock free. Anything else bearing such a name is left
// alone and named in a one-line note on standard error.

#include <filesystem>
#include <string>

namespace px {

// A hidden name for this run's temporary of `kind` ("tmp", "stage") for the target named `name`;
// "lock" gives the target's writer lock (OutputLock.h), the same for every run.
std::string temporaryName(const std::string& name, const char* kind);

// Takes a shared flock() on `fd`, the writer's sign of life on its temporary (see above).
void holdTemporary(int fd);

// Records this run's temporary `name` in the folder open as `dir` (kept open by the caller while
// registered); `self` is the temporary's own folder fd for a stage (-1 for a file). Returns a
// handle for releaseTemporary(); -1 when the table is full (then only a later run removes it).
int registerTemporary(int dir, const std::string& name, int self = -1);
void releaseTemporary(int handle);

// Removes every registered temporary, newest first; a stage with the files in it.
// Async-signal-safe (getdents64, unlinkat), for the CLI's SIGINT/SIGTERM handler.
void removeTemporariesNow() noexcept;

// Removes the provably dead leftovers of target `name` in the folder open as `dir`, or beside
// `target` (see above). Returns how many it removed.
int removeStaleTemporaries(int dir, const std::string& name);
int removeStaleTemporaries(const std::filesystem::path& target);

// Within an InterruptDeferral (a few renames that belong together), the CLI's signal handler only
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

// Fault injection, set only by tests (the fault suite's build of the CLI, in-process tests).
struct TestHooks {
    long long failWriteAt = -1; // a file's write fails with ENOSPC once this many bytes are written
    void (*reached)(const char* point) = nullptr; // called at each moment below
    float interruptAtProgress = -1.0f; // a command's progress raises SIGINT once this far (0..1)
};
void setTestHooks(const TestHooks& hooks);
const TestHooks& testHooks();
// Moments: "write" (half a file written), "commit" (before its rename), "export-commit" (every
// export file staged), "export-update" (half an update moved), "frames-commit", "frames-update".
void testInterruptPoint(const char* point);

// Registers a temporary by path for its lifetime (a plotting library's file).
class TemporaryGuard {
public:
    explicit TemporaryGuard(const std::filesystem::path& path);
    ~TemporaryGuard();
    TemporaryGuard(const TemporaryGuard&) = delete;
    TemporaryGuard& operator=(const TemporaryGuard&) = delete;

private:
    int m_dir = -1;
    int m_handle = -1;
};

} // namespace px

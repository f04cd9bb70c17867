#pragma once
// One writer at a time for an output made of several files (an export folder, a turntable's
// frames): an flock() on ".px-lock-<H>" beside the target (H hashes its name, Temporaries.h). A
// second writer is refused at once, naming the first one's process, rather than both finishing with
// one set silently winning. The kernel drops the lock of a killed process; the file itself is
// removed by whoever holds the lock when it lets go (the next run, after a kill), checked against
// its inode so that a run never holds a lock on a file another has just removed.

#include "parallax/Result.h"
#include "parallax/io/OutputGate.h"

#include <filesystem>
#include <string>

namespace px {

class OutputLock {
public:
    // Takes the lock of `target` (a file or folder path). Errors name the target and the process
    // holding it.
    static Result<OutputLock> take(const std::filesystem::path& target);
    OutputLock(OutputLock&& other) noexcept;
    OutputLock& operator=(OutputLock&&) = delete;
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;
    ~OutputLock(); // removes the lock file, then lets go

private:
    OutputLock() = default;
    UniqueFd m_dir, m_fd;
    std::string m_name;
    int m_handle = -1; // registered temporary: Ctrl-C removes the file too
};

} // namespace px

#pragma once
// The one gate every rename and delete goes through (docs/cli.md, "Nothing lost"): it replaces
// only regular files that are not inputs of this run (Inputs.h, by identity), never a folder, a
// special file or a link; a single file named through a link is written through it (outputTarget).
// Every act is relative to a folder the run opened (renameat, unlinkat, AT_SYMLINK_NOFOLLOW), so a
// link swapped in cannot redirect it. Temporaries.cpp (signal handler, leftover sweep) is the one
// other place that deletes; `build.OnlyTheGateDeletes` checks that no other code does.

#include "parallax/Result.h"

#include <filesystem>
#include <string>

namespace px {

// A file descriptor closed when it goes.
class UniqueFd {
public:
    explicit UniqueFd(int fd = -1) : m_fd(fd) {}
    UniqueFd(UniqueFd&& other) noexcept : m_fd(other.release()) {}
    UniqueFd& operator=(UniqueFd&& other) noexcept;
    UniqueFd(const UniqueFd&) = delete;
    UniqueFd& operator=(const UniqueFd&) = delete;
    ~UniqueFd();
    int get() const { return m_fd; }
    int release();

private:
    int m_fd;
};

// Opens the folder `folder` ("" is the working folder). Errors name it and the reason.
Result<UniqueFd> openFolder(const std::filesystem::path& folder);

// Whether a file may be written as `name` in the folder open as `dir` (AT_FDCWD: a path): absent,
// or a regular file that is not an input. Errors name `shown` and say what it is.
Status checkReplaceableAt(int dir, const std::string& name, const std::string& shown);
Status checkReplaceable(const std::filesystem::path& target);

// Where a single-file write named `path` goes: `path` itself, or, for a symbolic link, the
// regular file it leads to; then checkReplaceable. Errors name `path`.
Result<std::filesystem::path> outputTarget(const std::filesystem::path& path);

// Renames this run's own `from` (in `fromDir`) over `to` (in `toDir`) after checkReplaceableAt;
// with `folder`, `from` is a folder and `to` must be absent. On failure `from` stays.
Status replaceAt(int fromDir, const std::string& from, int toDir, const std::string& to,
                 const std::string& shown, bool folder = false);

// Removes the regular file `path` (`name` in `dir`); refuses inputs and other kinds, naming it.
Status removeOwned(const std::filesystem::path& path);
Status removeOwnedAt(int dir, const std::string& name, const std::string& shown);

// Removes this run's own temporary file or stage folder (with its files), best effort, through
// the folder fds (Temporaries.cpp).
void discardTemporary(const std::filesystem::path& path);
void discardTemporaryAt(int dir, const std::string& name);

} // namespace px

#pragma once
// The one gate every rename and delete of the project goes through (docs/cli.md, "Nothing lost").
// It replaces only regular files that are not inputs of this run (Inputs.h: by identity, so hard
// links and other spellings are caught), never a folder, a FIFO, a device, a socket or a symbolic
// link. A single file named through a symbolic link is written through it (outputTarget): the
// link's target, a regular file, is replaced atomically and the link stays a link, as an editor
// saves a linked document; a link to nothing or to a special file is refused. It deletes only what
// a caller can say is the project's own: this run's temporaries, the files an earlier export listed
// in its manifest, cache entries, and the leftovers of dead runs; and even those never when they
// are inputs. The signal handler's unlink() of this run's registered temporaries (Temporaries.cpp)
// is the one other place that deletes. `build.OnlyTheGateDeletes` checks that no other code does.

#include "parallax/Result.h"

#include <filesystem>

namespace px {

// Whether a file may be written at `target`: absent, or a regular file that is not an input.
// Errors name the target and say what it is.
Status checkReplaceable(const std::filesystem::path& target);

// Where a single-file write named `path` goes: `path` itself, or, for a symbolic link, the
// regular file it leads to; then checkReplaceable. Errors name `path`.
Result<std::filesystem::path> outputTarget(const std::filesystem::path& path);

// Renames this run's own `from` over `to`, after checkReplaceable(to). On failure `from` stays.
Status replaceWith(const std::filesystem::path& from, const std::filesystem::path& to);

// Moves this run's own folder `from` to `to`, which must be absent or an empty folder.
Status moveFolderInto(const std::filesystem::path& from, const std::filesystem::path& to);

// What a deletion is for: each is allowed only for the files the caller owns by that rule.
enum class Removal {
    EarlierExport, // a file an earlier export's manifest listed that this one does not write
    CacheEntry,    // a cache file the cache's own size limit evicts
    Leftover,      // a dead run's temporary (Temporaries.h)
    Unfinished,    // a file this run wrote for a result it then could not complete
};

// Removes the regular file (or, for a Leftover, the file or folder tree) at `path`. Refuses
// inputs and anything but a regular file, naming it; a Leftover tree keeps any input in it.
Status removeOwned(const std::filesystem::path& path, Removal why);

// Removes this run's own temporary file or folder tree, best effort (on an error path, or once
// it has served). Inputs in it are kept.
void discardTemporary(const std::filesystem::path& path);

} // namespace px

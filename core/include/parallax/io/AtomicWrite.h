#pragma once
// Every file the project writes goes to a temporary name in the target's folder and is renamed
// over the target only once complete (docs/conventions.md §6): a failure never leaves half a file.
// Every step is checked (each write, fsync, close) before the rename, so a full disk is an
// error naming the target and the reason, never a truncated file reported as success.

#include "parallax/Result.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace px {

// A hidden name beside `target` for a temporary (Temporaries.h), unique to this call.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Writes `contents` to `path` atomically: temporary file beside it, checked writes, fsync, rename,
// each relative to the folder opened once. The output gate refuses a target that is an input, a
// folder, a link or a special file before the temporary is made. Removes the provably dead
// leftovers of killed runs on the same target first (Temporaries.h). Within an OutputBatch the
// rename waits for the batch's commit.
Status writeFileAtomically(const std::string& path, std::string_view contents);

// Several files of one command written as one (bench's CSV and plot, import's material and
// derived height map): while a batch is open on this thread, each writeFileAtomically() is written
// and checked under its temporary name, and commit() renames them all with Ctrl-C deferred. A
// batch that ends uncommitted (an error, a full disk) removes its temporaries: nothing replaced.
// A batch opened inside another joins it.
class OutputBatch {
public:
    OutputBatch();
    ~OutputBatch();
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;
    // Every target is checked again, then every file renamed; errors name the target.
    Status commit();

    struct Staged;

private:
    std::vector<Staged>* m_own = nullptr; // null when joining an outer batch
};

// Writes `contents` to `path` atomically (text files: JSON, CSV, shaders, notes).
Status writeTextFile(const std::string& path, std::string_view contents);

// Reads a whole file (through InputFile: recorded as an input unless `record` is false, for the
// run's own files); errors name it.
Result<std::string> readTextFile(const std::string& path, bool record = true);

// The system's reason for errno `code`, e.g. "No space left on device".
std::string systemReason(int code);

} // namespace px

#pragma once
// Every file the project writes goes to a temporary name in the target's folder and is renamed
// over the target only once complete (docs/conventions.md §6): a failure never leaves half a file.
// Every step is checked (each write, fsync, close) before the rename, so a full disk is an
// error naming the target and the reason, never a truncated file reported as success.

#include "parallax/Result.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace px {

// A hidden name beside `target`, unique to this process and call (".NAME.tmpPID-N.HOST",
// Temporaries.h).
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Renames `temp` over `target` through the output gate (OutputGate.h); on failure removes `temp`
// and says why.
Status commitTemporary(const std::filesystem::path& temp, const std::filesystem::path& target);

// Writes `contents` to `path` atomically: temporary file, checked writes, fsync, rename. The
// output gate refuses a target that is an input, a folder, a link or a special file before the
// temporary is made. Removes the leftovers of killed runs on the same target first (see
// Temporaries.h).
// Test hook: PX_TEST_FAIL_WRITE_AT=N makes the write fail with ENOSPC once N bytes are written
// (the fault suite's full disk where it cannot mount a small tmpfs).
Status writeFileAtomically(const std::string& path, std::string_view contents);

// Writes `contents` to `path` atomically (text files: JSON, CSV, shaders, notes).
Status writeTextFile(const std::string& path, std::string_view contents);

// Reads a whole file (through InputFile: recorded as an input unless `record` is false, for the
// run's own files); errors name it.
Result<std::string> readTextFile(const std::string& path, bool record = true);

// The system's reason for errno `code`, e.g. "No space left on device".
std::string systemReason(int code);

} // namespace px

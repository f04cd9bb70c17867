#pragma once
// Every file the project writes goes to a temporary name in the target's folder and is renamed
// over the target only once complete (docs/conventions.md §6): a failure never leaves half a file.

#include "parallax/Result.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace px {

// A hidden name beside `target`, unique to this process and call.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Renames `temp` over `target`; on failure removes `temp` and says why.
Status commitTemporary(const std::filesystem::path& temp, const std::filesystem::path& target);

// Writes `contents` to `path` atomically.
Status writeTextFile(const std::string& path, std::string_view contents);

// Reads a whole file; errors name it.
Result<std::string> readTextFile(const std::string& path);

} // namespace px

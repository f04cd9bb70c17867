#pragma once
// An export folder written as a whole: files go into a hidden sibling of the target, which is
// renamed into place only once everything is there. A failure, a crash or Ctrl-C leave the target
// as it was (docs/conventions.md §6, for folders).
//
// Replacing an existing folder needs `force`, and even then only a folder that is empty or that a
// previous export wrote (it holds the marker file kExportMarker): --force must never wipe a folder
// of someone's other files because its name was mistyped.

#include "parallax/Result.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace px {

// Written into every export folder: what wrote it and the files it holds.
inline constexpr std::string_view kExportMarker = ".parallax-export";

class ExportFolder {
public:
    // Checks that `target` may be written (absent; or, with `force`, empty or a previous export),
    // creates its parent folders and the staging folder. Errors name the target.
    static Result<ExportFolder> begin(const std::filesystem::path& target, bool force);

    ExportFolder(ExportFolder&& other) noexcept;
    ExportFolder& operator=(ExportFolder&&) = delete;
    ExportFolder(const ExportFolder&) = delete;
    ~ExportFolder(); // removes the staging folder unless committed

    // Where to write a file of the export (a bare file name; no sub-folders).
    std::string pathFor(const std::string& name) const;
    // Records a file as part of the export (listed in the marker, returned by commit()).
    void add(const std::string& name) { m_files.push_back(name); }

    // Writes the marker, then swaps the staging folder into place (the previous folder, if any,
    // is removed afterwards). On failure the target is as it was.
    Result<std::vector<std::string>> commit(std::string_view description);

    const std::filesystem::path& target() const { return m_target; }

private:
    ExportFolder() = default;
    std::filesystem::path m_target;
    std::filesystem::path m_staging;
    std::vector<std::string> m_files;
    bool m_replace = false; // the target exists and is replaced
    bool m_done = false;
};

} // namespace px

#pragma once
// An export folder written as a whole (StagedSet.h): a new folder is staged beside the target and
// renamed into place once everything is there; an earlier export (or an existing folder, a mount
// point too) is staged inside and its files renamed in. A failure or Ctrl-C leave the target as it
// was (docs/conventions.md §6, for folders). One export at a time writes a
// folder (OutputLock.h): a second is refused, naming the first.
//
// Replacing an existing folder needs `force`, and even then only a folder that is empty or that a
// previous export wrote (it holds the marker file kExportMarker): --force must never wipe a folder
// of someone's other files because its name was mistyped. An earlier export is updated in place:
// each new file is renamed over its old self and nothing is removed: every other file (Unity .meta,
// Godot .import, a user's .mat, a file only the earlier export wrote) is kept and named, since
// engines keep their references to the textures in those files, and the marker that lists an
// earlier export's files is a file found on disk, which never decides a deletion. An update never
// replaces an input of the run (Inputs.h): an earlier export holding the material being exported,
// or one of its maps, is refused before anything is written.

#include "parallax/Result.h"
#include "parallax/io/OutputLock.h"
#include "parallax/io/StagedSet.h"

#include <filesystem>
#include <optional>
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

    ExportFolder(ExportFolder&& other) noexcept = default;
    ExportFolder& operator=(ExportFolder&&) = delete;
    ExportFolder(const ExportFolder&) = delete;
    ~ExportFolder() = default; // the stage goes unless committed, then the lock

    // Where to write a file of the export (a bare file name; no sub-folders).
    std::string pathFor(const std::string& name) const;
    // Records a file as part of the export (listed in the marker, returned by commit()).
    void add(const std::string& name) { m_files.push_back(name); }

    struct Committed {
        std::vector<std::string> files; // written, in order
        std::vector<std::string> kept; // files already in the folder that this export did not write
    };
    // Writes the marker, then moves the staging folder into place, or its files into an earlier
    // export (see above), and lets go of the folder's lock. On failure the target is as it was.
    Result<Committed> commit(std::string_view description);

    const std::filesystem::path& target() const { return m_target; }

    // An error about a staged file, told about the file the user will see: the hidden staging
    // folder's path replaced by the target's.
    Error asTarget(const Error& error) const;

private:
    ExportFolder(std::filesystem::path target, OutputLock lock, StagedSet stage)
        : m_target(std::move(target)), m_lock(std::move(lock)), m_stage(std::move(stage)) {}
    Result<Committed> commitStaged(std::string_view description);
    Result<Committed> updateInPlace(StagedSet::Update update);
    std::filesystem::path m_target;
    std::optional<OutputLock> m_lock; // declared before the stage: released after it is gone,
                                      // or once the export is in place
    StagedSet m_stage;
    std::vector<std::string> m_files;
    bool m_replace = false; // the target exists and is updated
};

} // namespace px

#include "parallax/export/ExportFolder.h"

#include "parallax/Version.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"
#include "parallax/io/Temporaries.h"

#include <algorithm>
#include <cerrno>
#include <sstream>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

namespace {

std::string where(const fs::path& path) {
    return path.string();
}

// The files an earlier export's marker lists (every line after the first). The marker is the
// project's own file, not an input.
std::vector<std::string> listedFiles(const fs::path& folder) {
    std::vector<std::string> files;
    Result<std::string> marker = readTextFile((folder / kExportMarker).string(), false);
    if (!marker)
        return files;
    std::istringstream lines(*marker);
    std::string line;
    std::getline(lines, line); // "Written by ..."
    while (std::getline(lines, line)) {
        // Bare names only: a marker edited to name "../x" must not reach outside the folder.
        if (!line.empty() && line.find('/') == std::string::npos && line != "." && line != "..")
            files.push_back(line);
    }
    return files;
}

bool contains(const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

// An earlier export's file that this run reads: the update would replace or remove it.
Status noInputAmong(const fs::path& target, const std::vector<std::string>& listed) {
    for (const std::string& name : listed) {
        const std::optional<FileIdentity> id = identityOf((target / name).string());
        if (!id)
            continue;
        if (const std::optional<InputEntry> input = inputWithIdentity(*id))
            return fileError(where(target),
                             "holds " + name +
                                 ", a file of the earlier export that this run reads as " +
                                 describeInput(*input) +
                                 ": updating the export would replace or remove it; export to "
                                 "another folder");
    }
    return success();
}

} // namespace

Result<ExportFolder> ExportFolder::begin(const fs::path& requested, bool force) {
    std::error_code ec;
    fs::path target = fs::absolute(requested, ec).lexically_normal();
    if (ec || requested.empty())
        return Error{"the output folder \"" + requested.string() + "\" is not a usable path"};
    if (target.filename().empty()) // "out/" names the folder "out"
        target = target.parent_path();
    if (target == target.root_path())
        return fileError(where(requested), "cannot export into the root folder");
    fs::create_directories(target.parent_path(), ec);
    if (ec)
        return fileError(target.parent_path().string(),
                         "cannot create the folder (" + ec.message() + ")");
    // One export at a time: the checks below and the commit see the same folder.
    Result<OutputLock> lock = OutputLock::take(target);
    if (!lock)
        return lock.error();
    removeStaleTemporaries(target); // a killed export's stage beside it, or in it (StagedSet.h)
    removeStaleTemporaries(target / target.filename());

    bool replace = false;
    std::vector<std::string> earlier;
    const fs::file_status status = fs::symlink_status(target, ec);
    if (fs::exists(status)) {
        if (fs::is_symlink(status))
            return fileError(where(requested),
                             "is a symbolic link (to " + fs::read_symlink(target, ec).string() +
                                 "); an export replaces whole folders: give the folder itself");
        if (!fs::is_directory(status))
            return fileError(where(requested), "exists and is not a folder; choose another output");
        const bool empty = fs::is_empty(target, ec);
        if (ec)
            return fileError(where(requested), "cannot read the folder (" + ec.message() + ")");
        if (!empty && !force)
            return fileError(where(requested), "already exists; use --force to replace it");
        if (!empty && !fs::exists(target / kExportMarker, ec))
            return fileError(where(requested),
                             "holds files that no export wrote; refusing to replace it even with "
                             "--force (empty it or choose another folder)");
        replace = true;
        earlier = listedFiles(target);
        if (Status s = noInputAmong(target, earlier); !s)
            return s.error();
    }
    Result<StagedSet> stage = StagedSet::begin(target, target.filename().string());
    if (!stage)
        return fileError(where(requested), "cannot create the export's working folder beside it (" +
                                               stage.error().message + ")");
    ExportFolder folder(target, std::move(*lock), std::move(*stage));
    folder.m_replace = replace;
    return folder;
}

std::string ExportFolder::pathFor(const std::string& name) const {
    return m_stage.pathFor(name);
}

Error ExportFolder::asTarget(const Error& error) const {
    auto replaced = [this](std::string text) {
        const std::string staging = m_stage.folder().string(), target = m_target.string();
        for (std::size_t at = text.find(staging); at != std::string::npos;
             at = text.find(staging, at + target.size()))
            text.replace(at, staging.size(), target);
        return text;
    };
    return Error(replaced(error.message), error.kind, replaced(error.file));
}

Result<ExportFolder::Committed> ExportFolder::commit(std::string_view description) {
    Result<Committed> committed = commitStaged(description);
    if (committed)
        m_lock.reset();
    return committed;
}

Result<ExportFolder::Committed> ExportFolder::commitStaged(std::string_view description) {
    std::string marker = "Written by Parallax Studio " + std::string(kVersion) + ": " +
                         std::string(description) + "\n";
    for (const std::string& file : m_files)
        marker += file + "\n";
    if (Status s = writeTextFile(pathFor(std::string(kExportMarker)), marker); !s)
        return asTarget(s.error());
    StagedSet::Update update;
    update.commitPoint = "export-commit";
    if (!m_replace) {
        if (Status s = m_stage.commit(update); !s)
            return fileError(where(m_target),
                             "cannot move the export into place (" + s.error().message + ")");
        return Committed{m_files, {}};
    }
    return updateInPlace(std::move(update));
}

// An update replaces the files this export writes and removes nothing: a file the earlier export
// wrote that this one does not is kept and named, since the marker that lists it is a file found
// on disk, and what such a file says is never a reason to delete.
Result<ExportFolder::Committed> ExportFolder::updateInPlace(StagedSet::Update update) {
    // Everything that can be checked is checked before the first file moves.
    if (::access(m_target.c_str(), W_OK | X_OK) != 0)
        return fileError(where(m_target), "cannot update the earlier export (" +
                                              systemReason(errno) + "); it is unchanged");
    update.moves.emplace_back(kExportMarker);
    update.moves.insert(update.moves.end(), m_files.begin(), m_files.end());
    update.updatePoint = "export-update";
    if (Status s = m_stage.commit(update); !s)
        return s.error();
    Committed result{m_files, {}};
    std::error_code ec;
    for (fs::directory_iterator it(m_target, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name != kExportMarker && !contains(m_files, name))
            result.kept.push_back(name);
    }
    std::sort(result.kept.begin(), result.kept.end());
    return result;
}

} // namespace px

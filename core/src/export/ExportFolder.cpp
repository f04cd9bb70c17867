#include "parallax/export/ExportFolder.h"

#include "parallax/Version.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Temporaries.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <sstream>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

namespace {

// A hidden sibling of `target`, unique to this process and call.
fs::path siblingFor(const fs::path& target, const char* role) {
    static std::atomic<unsigned> counter{0};
    return target.parent_path() / ("." + target.filename().string() + "." + role +
                                   std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

std::string where(const fs::path& path) {
    return path.string();
}

// The files an earlier export's marker lists (every line after the first).
std::vector<std::string> listedFiles(const fs::path& folder) {
    std::vector<std::string> files;
    Result<std::string> marker = readTextFile((folder / kExportMarker).string());
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

    ExportFolder folder;
    folder.m_target = target;
    if (fs::exists(fs::symlink_status(target, ec))) {
        if (!fs::is_directory(fs::symlink_status(target, ec)))
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
        folder.m_replace = true;
    }
    fs::create_directories(target.parent_path(), ec);
    if (!ec)
        removeStaleTemporaries(target); // what a killed export left beside it
    if (ec)
        return fileError(target.parent_path().string(),
                         "cannot create the folder (" + ec.message() + ")");
    folder.m_staging = siblingFor(target, "export-tmp");
    if (!fs::create_directory(folder.m_staging, ec) || ec)
        return fileError(where(requested),
                         "cannot create the export's working folder beside it in " +
                             target.parent_path().string() + " (" +
                             (ec ? ec.message() : std::string("it exists")) + ")");
    folder.m_stagingHandle = registerTemporary(folder.m_staging);
    return folder;
}

ExportFolder::ExportFolder(ExportFolder&& other) noexcept
    : m_target(std::move(other.m_target)), m_staging(std::move(other.m_staging)),
      m_files(std::move(other.m_files)), m_stagingHandle(other.m_stagingHandle),
      m_fileHandles(std::move(other.m_fileHandles)), m_replace(other.m_replace),
      m_done(other.m_done) {
    other.m_staging.clear();
    other.m_stagingHandle = -1;
    other.m_fileHandles.clear();
    other.m_done = true;
}

ExportFolder::~ExportFolder() {
    if (!m_done && !m_staging.empty()) {
        std::error_code ignored;
        fs::remove_all(m_staging, ignored);
    }
    for (int handle : m_fileHandles)
        releaseTemporary(handle);
    releaseTemporary(m_stagingHandle);
}

std::string ExportFolder::pathFor(const std::string& name) const {
    // Registered so that Ctrl-C removes it before the staging folder (newest first).
    const fs::path path = m_staging / name;
    m_fileHandles.push_back(registerTemporary(path));
    return path.string();
}

Error ExportFolder::asTarget(const Error& error) const {
    auto replaced = [this](std::string text) {
        const std::string staging = m_staging.string(), target = m_target.string();
        for (std::size_t at = text.find(staging); at != std::string::npos;
             at = text.find(staging, at + target.size()))
            text.replace(at, staging.size(), target);
        return text;
    };
    return Error(replaced(error.message), error.kind, replaced(error.file));
}

Result<ExportFolder::Committed> ExportFolder::commit(std::string_view description) {
    std::string marker = "Written by Parallax Studio " + std::string(kVersion) + ": " +
                         std::string(description) + "\n";
    for (const std::string& file : m_files)
        marker += file + "\n";
    if (Status s = writeTextFile(pathFor(std::string(kExportMarker)), marker); !s)
        return s.error();

    testInterruptPoint("export-commit");
    std::error_code ec;
    if (!m_replace) {
        fs::rename(m_staging, m_target, ec); // also replaces an empty folder
        if (ec)
            return fileError(where(m_target),
                             "cannot move the export into place (" + ec.message() + ")");
        m_done = true;
        return Committed{m_files, {}};
    }
    return updateInPlace();
}

Result<ExportFolder::Committed> ExportFolder::updateInPlace() {
    // Everything that can be checked is checked before the first file moves.
    if (::access(m_target.c_str(), W_OK | X_OK) != 0)
        return fileError(where(m_target), "cannot update the earlier export (" +
                                              systemReason(errno) + "); it is unchanged");
    std::error_code ec;
    for (const std::string& name : m_files) {
        if (fs::is_directory(m_target / name, ec))
            return fileError((m_target / name).string(),
                             "is a folder where the export writes a file; it is unchanged");
    }
    const std::vector<std::string> earlier = listedFiles(m_target);
    Committed result{m_files, {}};
    {
        const InterruptDeferral deferral; // a half-updated folder is worse than a finished one
        for (const std::string& name : m_files) {
            if (&name == &m_files[m_files.size() / 2])
                testInterruptPoint("export-update");
            fs::rename(m_staging / name, m_target / name, ec);
            if (ec)
                return fileError((m_target / name).string(),
                                 "cannot replace the file (" + ec.message() + ")");
        }
        for (const std::string& name : earlier) {
            if (!contains(m_files, name))
                fs::remove(m_target / name, ec);
        }
        fs::rename(m_staging / kExportMarker, m_target / kExportMarker, ec);
        if (ec)
            return fileError(where(m_target / kExportMarker),
                             "cannot replace the file (" + ec.message() + ")");
        m_done = true;
        fs::remove_all(m_staging, ec);
    }
    for (fs::directory_iterator it(m_target, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name != kExportMarker && !contains(m_files, name))
            result.kept.push_back(name);
    }
    std::sort(result.kept.begin(), result.kept.end());
    return result;
}

} // namespace px

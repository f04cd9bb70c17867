#include "parallax/export/ExportFolder.h"

#include "parallax/Version.h"
#include "parallax/io/AtomicWrite.h"

#include <atomic>
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
    if (ec)
        return fileError(target.parent_path().string(),
                         "cannot create the folder (" + ec.message() + ")");
    folder.m_staging = siblingFor(target, "export-tmp");
    if (!fs::create_directory(folder.m_staging, ec) || ec)
        return fileError(target.parent_path().string(),
                         "cannot create a folder there (" +
                             (ec ? ec.message() : std::string("it exists")) + ")");
    return folder;
}

ExportFolder::ExportFolder(ExportFolder&& other) noexcept
    : m_target(std::move(other.m_target)), m_staging(std::move(other.m_staging)),
      m_files(std::move(other.m_files)), m_replace(other.m_replace), m_done(other.m_done) {
    other.m_staging.clear();
    other.m_done = true;
}

ExportFolder::~ExportFolder() {
    if (!m_done && !m_staging.empty()) {
        std::error_code ignored;
        fs::remove_all(m_staging, ignored);
    }
}

std::string ExportFolder::pathFor(const std::string& name) const {
    return (m_staging / name).string();
}

Result<std::vector<std::string>> ExportFolder::commit(std::string_view description) {
    std::string marker = "Written by Parallax Studio " + std::string(kVersion) + ": " +
                         std::string(description) + "\n";
    for (const std::string& file : m_files)
        marker += file + "\n";
    if (Status s = writeTextFile(pathFor(std::string(kExportMarker)), marker); !s)
        return s.error();

    std::error_code ec;
    if (!m_replace) {
        fs::rename(m_staging, m_target, ec); // also replaces an empty folder
        if (ec)
            return fileError(where(m_target),
                             "cannot move the export into place (" + ec.message() + ")");
        m_done = true;
        return m_files;
    }
    // Swap: target -> old, staging -> target; put the old folder back if the second step fails.
    const fs::path old = siblingFor(m_target, "export-old");
    fs::rename(m_target, old, ec);
    if (ec)
        return fileError(where(m_target), "cannot replace the folder (" + ec.message() + ")");
    fs::rename(m_staging, m_target, ec);
    if (ec) {
        std::error_code ignored;
        fs::rename(old, m_target, ignored);
        return fileError(where(m_target),
                         "cannot move the export into place (" + ec.message() + ")");
    }
    m_done = true;
    fs::remove_all(old, ec); // the new export is in place; a leftover is only clutter
    return m_files;
}

} // namespace px

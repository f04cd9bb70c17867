#include "parallax/io/OutputGate.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <optional>
#include <sys/stat.h>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

namespace {

std::optional<InputEntry> inputAt(const struct stat& st) {
    return inputWithIdentity(
        {static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)});
}

std::string linkTarget(int dir, const std::string& name) {
    char to[4096];
    const ssize_t n = ::readlinkat(dir, name.c_str(), to, sizeof to);
    return n <= 0 ? std::string() : " (to " + std::string(to, static_cast<std::size_t>(n)) + ")";
}

} // namespace

UniqueFd& UniqueFd::operator=(UniqueFd&& other) noexcept {
    if (this != &other) {
        if (m_fd >= 0)
            ::close(m_fd);
        m_fd = other.release();
    }
    return *this;
}

UniqueFd::~UniqueFd() {
    if (m_fd >= 0)
        ::close(m_fd);
}

int UniqueFd::release() {
    const int fd = m_fd;
    m_fd = -1;
    return fd;
}

Result<UniqueFd> openFolder(const fs::path& folder) {
    const fs::path dir = folder.empty() ? fs::path(".") : folder;
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENOENT || errno == ENOTDIR)
            return fileError(dir.string(), "the folder does not exist");
        return fileError(dir.string(), "cannot open the folder (" + systemReason(errno) + ")");
    }
    return UniqueFd(fd);
}

Status checkReplaceableAt(int dir, const std::string& name, const std::string& shown) {
    struct stat st {};
    if (::fstatat(dir, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0)
        return success(); // absent (or unreachable: creating the file says why)
    if (S_ISDIR(st.st_mode))
        return fileError(shown, "is a folder; give a file name");
    if (S_ISLNK(st.st_mode))
        return fileError(shown, "is a symbolic link" + linkTarget(dir, name) +
                                    ": refusing to replace it; write to the file it points to, "
                                    "or remove the link");
    if (!S_ISREG(st.st_mode))
        return fileError(shown, "is " + fileKind(st.st_mode) +
                                    ", not a regular file: refusing to replace it");
    if (const std::optional<InputEntry> input = inputAt(st))
        return fileError(shown, "is the same file as " + describeInput(*input) +
                                    ", which this run reads: refusing to overwrite or delete an "
                                    "input; choose another output");
    return success();
}

Status checkReplaceable(const fs::path& target) {
    return checkReplaceableAt(AT_FDCWD, target.string(), target.string());
}

Result<fs::path> outputTarget(const fs::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
        if (Status s = checkReplaceable(path); !s)
            return s.error();
        return path;
    }
    std::error_code ec;
    const fs::path real = fs::canonical(path, ec);
    if (ec)
        return fileError(path.string(), "is a symbolic link" + linkTarget(AT_FDCWD, path) +
                                            " to nothing that exists: refusing to create a file "
                                            "there; name the file itself");
    if (Status s = checkReplaceable(real); !s)
        return fileError(path.string(), "is a symbolic link to " + real.string() + ", which " +
                                            s.error().message.substr(real.string().size() + 2));
    return real;
}

Status replaceAt(int fromDir, const std::string& from, int toDir, const std::string& to,
                 const std::string& shown, bool folder) {
    if (folder) {
        // Never over anything: the target was absent when the stage was made beside it.
        // (A file system without RENAME_NOREPLACE: rename() replaces at most an empty folder.)
        if (::renameat2(fromDir, from.c_str(), toDir, to.c_str(), RENAME_NOREPLACE) != 0 &&
            (errno != EINVAL || ::renameat(fromDir, from.c_str(), toDir, to.c_str()) != 0))
            return fileError(shown,
                             "cannot move the folder into place (" + systemReason(errno) + ")");
        return success();
    }
    if (Status s = checkReplaceableAt(toDir, to, shown); !s)
        return s;
    if (::renameat(fromDir, from.c_str(), toDir, to.c_str()) != 0)
        return fileError(shown, "cannot replace the file (" + systemReason(errno) + ")");
    return success();
}

Status removeOwnedAt(int dir, const std::string& name, const std::string& shown) {
    struct stat st {};
    if (::fstatat(dir, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0)
        return success();
    if (!S_ISREG(st.st_mode))
        return fileError(shown,
                         "is " + fileKind(st.st_mode) + ", not a file the project wrote; kept");
    if (Status s = checkReplaceableAt(dir, name, shown); !s)
        return s;
    if (::unlinkat(dir, name.c_str(), 0) != 0 && errno != ENOENT)
        return fileError(shown, "cannot remove the file (" + systemReason(errno) + ")");
    return success();
}

Status removeOwned(const fs::path& path) {
    return removeOwnedAt(AT_FDCWD, path.string(), path.string());
}

void discardTemporary(const fs::path& path) {
    discardTemporaryAt(AT_FDCWD, path.string());
}

} // namespace px

#include "parallax/io/OutputGate.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"

#include <cerrno>
#include <cstdio>
#include <dirent.h>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace px {

namespace fs = std::filesystem;

namespace {

std::optional<InputEntry> inputAt(const struct stat& st) {
    return inputWithIdentity(
        {static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)});
}

Error isAnInput(const fs::path& path, const InputEntry& input) {
    return fileError(path.string(), "is the same file as " + describeInput(input) +
                                        ", which this run reads: refusing to overwrite or delete "
                                        "an input; choose another output");
}

std::string linkTarget(const fs::path& link) {
    std::error_code ec;
    const fs::path to = fs::read_symlink(link, ec);
    return ec ? std::string() : " (to " + to.string() + ")";
}

// Removes a tree of the project's own files, keeping any input found in it (and so its folders).
// Returns whether everything went.
bool removeTree(const fs::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0)
        return errno == ENOENT;
    if (inputAt(st))
        return false;
    if (!S_ISDIR(st.st_mode))
        return ::unlink(path.c_str()) == 0 || errno == ENOENT;
    bool all = true;
    if (DIR* dir = ::opendir(path.c_str())) {
        std::vector<std::string> names;
        while (const dirent* entry = ::readdir(dir)) {
            const std::string name = entry->d_name;
            if (name != "." && name != "..")
                names.push_back(name);
        }
        ::closedir(dir);
        for (const std::string& name : names)
            all = removeTree(path / name) && all;
    }
    return all && ::rmdir(path.c_str()) == 0;
}

} // namespace

Status checkReplaceable(const fs::path& target) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0)
        return success(); // absent (or unreachable: creating the file says why)
    if (S_ISDIR(st.st_mode))
        return fileError(target.string(), "is a folder; give a file name");
    if (S_ISLNK(st.st_mode))
        return fileError(target.string(),
                         "is a symbolic link" + linkTarget(target) +
                             ": refusing to replace it; write to the file it points to, or "
                             "remove the link");
    if (!S_ISREG(st.st_mode))
        return fileError(target.string(), "is " + fileKind(st.st_mode) +
                                              ", not a regular file: refusing to replace it");
    if (const std::optional<InputEntry> input = inputAt(st))
        return isAnInput(target, *input);
    return success();
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
        return fileError(path.string(), "is a symbolic link" + linkTarget(path) +
                                            " to nothing that exists: refusing to create a file "
                                            "there; name the file itself");
    if (Status s = checkReplaceable(real); !s)
        return fileError(path.string(), "is a symbolic link to " + real.string() + ", which " +
                                            s.error().message.substr(real.string().size() + 2));
    return real;
}

Status replaceWith(const fs::path& from, const fs::path& to) {
    if (Status s = checkReplaceable(to); !s)
        return s;
    if (::rename(from.c_str(), to.c_str()) != 0)
        return fileError(to.string(), "cannot replace the file (" + systemReason(errno) + ")");
    return success();
}

Status moveFolderInto(const fs::path& from, const fs::path& to) {
    struct stat st {};
    if (::lstat(to.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        return fileError(to.string(), "is " + fileKind(st.st_mode) + ", not a folder");
    // rename() replaces only an empty folder, atomically.
    if (::rename(from.c_str(), to.c_str()) != 0)
        return fileError(to.string(),
                         "cannot move the folder into place (" + systemReason(errno) + ")");
    return success();
}

Status removeOwned(const fs::path& path, Removal why) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0)
        return success();
    if (const std::optional<InputEntry> input = inputAt(st))
        return isAnInput(path, *input);
    if (why == Removal::Leftover) {
        if (!removeTree(path))
            return fileError(path.string(), "could not be removed entirely");
        return success();
    }
    if (!S_ISREG(st.st_mode))
        return fileError(path.string(),
                         "is " + fileKind(st.st_mode) + ", not a file the project wrote; kept");
    if (::unlink(path.c_str()) != 0 && errno != ENOENT)
        return fileError(path.string(), "cannot remove the file (" + systemReason(errno) + ")");
    return success();
}

void discardTemporary(const fs::path& path) {
    removeTree(path);
}

} // namespace px

#include "parallax/io/AtomicWrite.h"

#include "parallax/io/Inputs.h"
#include "parallax/io/OutputGate.h"
#include "parallax/io/Temporaries.h"

#include <algorithm>
#include <cerrno>
#include <fcntl.h>
#include <limits>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

// A file written under its temporary name, waiting for its batch's commit.
struct OutputBatch::Staged {
    UniqueFd dir, file;
    std::string temp, name, shown;
    int handle = -1;
};

namespace {

thread_local std::vector<OutputBatch::Staged>* tBatch = nullptr;

// Writes every byte or returns the errno that stopped it (0 on success). `offset`: bytes of the
// file already written (for the test hook's full disk).
int writeAll(int fd, std::string_view bytes, long long offset = 0) {
    const long long failAt = testHooks().failWriteAt;
    std::size_t done = 0;
    while (done < bytes.size()) {
        std::size_t chunk = bytes.size() - done;
        if (failAt >= 0) {
            const long long left = failAt - offset - static_cast<long long>(done);
            if (left <= 0)
                return ENOSPC;
            chunk = std::min<std::size_t>(chunk, static_cast<std::size_t>(left));
        }
        const ssize_t n = ::write(fd, bytes.data() + done, chunk);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return n < 0 ? errno : EIO;
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

Error createError(const std::string& path, int code) {
    const fs::path folder = fs::path(path).parent_path();
    if ((code == ENOENT || code == ENOTDIR) && !folder.empty())
        return fileError(path, "cannot create the file: the folder " + folder.string() +
                                   " does not exist");
    return fileError(path, "cannot create the file (" + systemReason(code) + ")");
}

void discard(OutputBatch::Staged& staged) {
    discardTemporaryAt(staged.dir.get(), staged.temp);
    releaseTemporary(staged.handle);
}

Status commitOne(OutputBatch::Staged& staged) {
    testInterruptPoint("commit");
    struct stat st {};
    if (::fstat(staged.file.get(), &st) == 0)
        noteCreated({static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)});
    Status s =
        replaceAt(staged.dir.get(), staged.temp, staged.dir.get(), staged.name, staged.shown);
    if (!s)
        discardTemporaryAt(staged.dir.get(), staged.temp);
    releaseTemporary(staged.handle);
    return s;
}

} // namespace

std::string systemReason(int code) {
    return std::error_code(code, std::generic_category()).message();
}

fs::path temporaryPathFor(const fs::path& target) {
    return target.parent_path() / temporaryName(target.filename().string(), "tmp");
}

Status writeFileAtomically(const std::string& path, std::string_view contents) {
    // The file itself, or a symbolic link's regular target (the link stays); not an input, not a
    // folder or a special file.
    Result<fs::path> resolved = outputTarget(path);
    if (!resolved)
        return resolved.error();
    const fs::path target = *resolved;
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    OutputBatch::Staged staged;
    staged.dir = UniqueFd(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (staged.dir.get() < 0)
        return createError(path, errno);
    staged.name = target.filename().string();
    staged.shown = target != fs::path(path) ? path + " (a link to " + target.string() + ")" : path;
    // A set's stage is this run's own folder: nothing to sweep in it, and its StagedSet, never a
    // batch, commits it.
    const bool inStage = folder.filename().string().starts_with(".px-stage-");
    if (!inStage)
        removeStaleTemporaries(staged.dir.get(), staged.name);
    staged.temp = temporaryName(staged.name, "tmp");
    staged.file = UniqueFd(::openat(staged.dir.get(), staged.temp.c_str(),
                                    O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666));
    if (staged.file.get() < 0)
        return createError(path, errno);
    staged.handle = registerTemporary(staged.dir.get(), staged.temp);
    holdTemporary(staged.file.get()); // until renamed: no other run's sweep takes it meanwhile
    struct stat st {};
    if (::fstatat(staged.dir.get(), staged.name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0)
        ::fchmod(staged.file.get(), st.st_mode & 07777); // keep the replaced file's permissions
    const std::size_t half = contents.size() / 2;
    int code = writeAll(staged.file.get(), contents.substr(0, half));
    testInterruptPoint("write");
    if (code == 0)
        code = writeAll(staged.file.get(), contents.substr(half), static_cast<long long>(half));
    if (code == 0 && ::fsync(staged.file.get()) != 0)
        code = errno;
    if (code != 0) {
        discard(staged);
        return fileError(path, "writing failed (" + systemReason(code) +
                                   "); the previous file, if any, is unchanged");
    }
    if (tBatch != nullptr && !inStage) {
        tBatch->push_back(std::move(staged));
        return success();
    }
    return commitOne(staged);
}

OutputBatch::OutputBatch() {
    if (tBatch == nullptr) {
        m_own = new std::vector<Staged>;
        tBatch = m_own;
    }
}

OutputBatch::~OutputBatch() {
    if (m_own == nullptr)
        return;
    tBatch = nullptr;
    for (Staged& staged : *m_own)
        discard(staged);
    delete m_own;
}

Status OutputBatch::commit() {
    if (m_own == nullptr)
        return success(); // the outer batch commits
    tBatch = nullptr;
    for (Staged& staged : *m_own) { // nothing renamed while any target is refused
        if (Status s = checkReplaceableAt(staged.dir.get(), staged.name, staged.shown); !s)
            return s;
    }
    const InterruptDeferral deferral;
    Status result = success();
    for (Staged& staged : *m_own) {
        if (Status s = commitOne(staged); !s && result)
            result = s;
    }
    m_own->clear();
    return result;
}

Status writeTextFile(const std::string& path, std::string_view contents) {
    return writeFileAtomically(path, contents);
}

Result<std::string> readTextFile(const std::string& path, bool record) {
    Result<InputFile> file = InputFile::open(path, {}, record);
    if (!file)
        return file.error();
    return file->readAll(std::numeric_limits<std::uint64_t>::max());
}

} // namespace px

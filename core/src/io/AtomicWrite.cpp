#include "parallax/io/AtomicWrite.h"

#include "parallax/io/Inputs.h"
#include "parallax/io/OutputGate.h"
#include "parallax/io/Temporaries.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

namespace {

// PX_TEST_FAIL_WRITE_AT=N: the byte count after which writes fail with ENOSPC (-1: never).
long long injectedFullDiskAt() {
    const char* at = std::getenv("PX_TEST_FAIL_WRITE_AT");
    return at != nullptr ? std::atoll(at) : -1;
}

// Writes every byte or returns the errno that stopped it (0 on success). `offset`: bytes of the
// file already written (for the injected full disk).
int writeAll(int fd, std::string_view bytes, long long offset = 0) {
    const long long limit = injectedFullDiskAt() - offset;
    const bool injected = injectedFullDiskAt() >= 0;
    std::size_t done = 0;
    while (done < bytes.size()) {
        std::size_t chunk = bytes.size() - done;
        if (injected) {
            if (static_cast<long long>(done) >= limit)
                return ENOSPC;
            chunk = std::min<std::size_t>(
                chunk, static_cast<std::size_t>(limit - static_cast<long long>(done)));
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
    std::error_code ec;
    if (code == ENOENT && !folder.empty() && !fs::is_directory(folder, ec))
        return fileError(path, "cannot create the file: the folder " + folder.string() +
                                   " does not exist");
    return fileError(path, "cannot create the file (" + systemReason(code) + ")");
}

} // namespace

std::string systemReason(int code) {
    return std::error_code(code, std::generic_category()).message();
}

fs::path temporaryPathFor(const fs::path& target) {
    return temporarySibling(target, "tmp");
}

Status commitTemporary(const fs::path& temp, const fs::path& target) {
    if (Status s = replaceWith(temp, target); !s) {
        discardTemporary(temp);
        return s;
    }
    return success();
}

Status writeFileAtomically(const std::string& path, std::string_view contents) {
    // The file itself, or a symbolic link's regular target (the link stays); not an input, not a
    // folder or a special file.
    Result<fs::path> resolved = outputTarget(path);
    if (!resolved)
        return resolved.error();
    const fs::path target = *resolved;
    removeStaleTemporaries(target);
    const fs::path temp = temporaryPathFor(target);
    TemporaryGuard guard(temp);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        return createError(path, errno);
    holdTemporary(fd); // until renamed: no other run's sweep takes it meanwhile
    struct stat st {};
    if (::lstat(target.c_str(), &st) == 0) // keep the replaced file's permissions
        ::fchmod(fd, st.st_mode & 07777);
    const std::size_t half = contents.size() / 2;
    int code = writeAll(fd, contents.substr(0, half));
    testInterruptPoint("write");
    if (code == 0)
        code = writeAll(fd, contents.substr(half), static_cast<long long>(half));
    if (code == 0 && ::fsync(fd) != 0)
        code = errno;
    if (code != 0) {
        ::close(fd);
        discardTemporary(temp);
        return fileError(path, "writing failed (" + systemReason(code) +
                                   "); the previous file, if any, is unchanged");
    }
    testInterruptPoint("commit");
    if (::fstat(fd, &st) == 0)
        noteCreated({static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)});
    Status committed = commitTemporary(temp, target);
    ::close(fd);
    if (!committed && target != fs::path(path)) // name the file as the user did
        return fileError(path, "(a link to " + target.string() + "): " + committed.error().message);
    return committed;
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

#include "parallax/io/AtomicWrite.h"

#include "parallax/io/Temporaries.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
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
    static std::atomic<unsigned> counter{0};
    return target.parent_path() / ("." + target.filename().string() + ".tmp" +
                                   std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

Status commitTemporary(const fs::path& temp, const fs::path& target) {
    std::error_code ec;
    if (fs::is_directory(target, ec)) {
        fs::remove(temp, ec);
        return fileError(target.string(), "is a folder; give a file name");
    }
    fs::rename(temp, target, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        return fileError(target.string(), "cannot replace the file (" + ec.message() + ")");
    }
    return success();
}

Status writeFileAtomically(const std::string& path, std::string_view contents) {
    const fs::path target(path);
    std::error_code ec;
    if (fs::is_directory(target, ec))
        return fileError(path, "is a folder; give a file name");
    removeStaleTemporaries(target);
    const fs::path temp = temporaryPathFor(target);
    TemporaryGuard guard(temp);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        return createError(path, errno);
    struct stat previous {};
    if (::stat(target.c_str(), &previous) == 0) // keep the replaced file's permissions
        ::fchmod(fd, previous.st_mode & 07777);
    const std::size_t half = contents.size() / 2;
    int code = writeAll(fd, contents.substr(0, half));
    testInterruptPoint("write");
    if (code == 0)
        code = writeAll(fd, contents.substr(half), static_cast<long long>(half));
    if (code == 0 && ::fsync(fd) != 0)
        code = errno;
    if (::close(fd) != 0 && code == 0)
        code = errno;
    if (code != 0) {
        fs::remove(temp, ec);
        return fileError(path, "writing failed (" + systemReason(code) +
                                   "); the previous file, if any, is unchanged");
    }
    testInterruptPoint("commit");
    return commitTemporary(temp, target);
}

Status writeTextFile(const std::string& path, std::string_view contents) {
    return writeFileAtomically(path, contents);
}

Result<std::string> readTextFile(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec))
        return fileError(path, "no such file");
    if (fs::is_directory(path, ec))
        return fileError(path, "is a folder, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return fileError(path, "cannot open the file for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad())
        return fileError(path, "reading failed");
    return buffer.str();
}

} // namespace px

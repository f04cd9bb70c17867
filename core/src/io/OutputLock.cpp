#include "parallax/io/OutputLock.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"
#include "parallax/io/OutputGate.h"
#include "parallax/io/Temporaries.h"

#include <cerrno>
#include <fcntl.h>
#include <string>
#include <string_view>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace px {

namespace fs = std::filesystem;

namespace {

// What the holder wrote into the lock: "pid 1234".
std::string holderOf(int fd) {
    char text[64] = {};
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    std::string holder = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string();
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' '))
        holder.pop_back();
    return holder.empty() ? std::string("another process") : "process " + holder;
}

// A lock file is ours only when it holds what a holder writes: its pid and a newline, or nothing
// (a holder killed before writing it). Anything else is someone's file that happens to bear the
// name: it is neither truncated nor removed.
bool holdsALockOfOurs(int fd, const struct stat& st) {
    if (st.st_size == 0)
        return true;
    char text[16] = {};
    if (st.st_size > static_cast<off_t>(sizeof text) ||
        ::pread(fd, text, sizeof text, 0) != st.st_size)
        return false;
    const std::string_view pid(text, static_cast<std::size_t>(st.st_size) - 1);
    return text[st.st_size - 1] == '\n' && !pid.empty() &&
           pid.find_first_not_of("0123456789") == std::string_view::npos;
}

} // namespace

Result<OutputLock> OutputLock::take(const fs::path& requested) {
    fs::path target = requested;
    if (target.filename().empty()) // "out/" names "out"
        target = target.parent_path();
    const fs::path path = target.parent_path() / ("." + target.filename().string() + ".lock");
    for (int attempt = 0; attempt < 100; ++attempt) {
        const int fd =
            ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
        if (fd < 0)
            return fileError(target.string(), "cannot take the writer's lock " + path.string() +
                                                  " (" + systemReason(errno) + ")");
        struct stat held {};
        if (::fstat(fd, &held) != 0 || !S_ISREG(held.st_mode)) {
            ::close(fd);
            return fileError(target.string(), "the writer's lock " + path.string() +
                                                  " is not a regular file; remove it");
        }
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const std::string holder = holderOf(fd);
            ::close(fd);
            return fileError(target.string(),
                             "another run (" + holder +
                                 ") is writing it now; nothing was changed: run again once it "
                                 "has finished");
        }
        // The previous holder may have removed the file between our open and our lock: then
        // this lock guards nothing, and another run may already hold a new file's.
        struct stat now {};
        if (::stat(path.c_str(), &now) != 0 || now.st_ino != held.st_ino ||
            now.st_dev != held.st_dev) {
            ::close(fd);
            continue;
        }
        const FileIdentity id{static_cast<std::uint64_t>(held.st_dev),
                              static_cast<std::uint64_t>(held.st_ino)};
        if (!holdsALockOfOurs(fd, now) || inputWithIdentity(id)) {
            ::close(fd);
            return fileError(target.string(),
                             "the writer's lock " + path.string() +
                                 " is a file that Parallax Studio did not write; refusing to "
                                 "replace it (rename it, or choose another output)");
        }
        const std::string pid = std::to_string(::getpid()) + "\n";
        if (::ftruncate(fd, 0) == 0) [[maybe_unused]]
            const ssize_t n = ::pwrite(fd, pid.data(), pid.size(), 0);
        noteCreated(id);
        OutputLock lock;
        lock.m_path = path;
        lock.m_fd = fd;
        lock.m_handle = registerTemporary(path);
        return lock;
    }
    return fileError(target.string(), "cannot take the writer's lock " + path.string() +
                                          ": it keeps being replaced");
}

OutputLock::OutputLock(OutputLock&& other) noexcept
    : m_path(std::move(other.m_path)), m_fd(other.m_fd), m_handle(other.m_handle) {
    other.m_fd = -1;
    other.m_handle = -1;
}

OutputLock::~OutputLock() {
    if (m_fd < 0)
        return;
    discardTemporary(m_path); // while still held: see the check after flock() above
    releaseTemporary(m_handle);
    ::close(m_fd);
}

} // namespace px

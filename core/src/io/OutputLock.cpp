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
    Result<UniqueFd> dir = openFolder(target.parent_path());
    if (!dir)
        return dir.error();
    const std::string name = temporaryName(target.filename().string(), "lock");
    const std::string shown = (target.parent_path() / name).string();
    for (int attempt = 0; attempt < 100; ++attempt) {
        UniqueFd fd(::openat(dir->get(), name.c_str(),
                             O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644));
        if (fd.get() < 0)
            return fileError(target.string(), "cannot take the writer's lock " + shown + " (" +
                                                  systemReason(errno) + ")");
        struct stat held {};
        if (::fstat(fd.get(), &held) != 0 || !S_ISREG(held.st_mode))
            return fileError(target.string(),
                             "the writer's lock " + shown + " is not a regular file; remove it");
        if (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0)
            return fileError(target.string(),
                             "another run (" + holderOf(fd.get()) +
                                 ") is writing it now; nothing was changed: run again once it "
                                 "has finished");
        // The previous holder may have removed the file between our open and our lock: then
        // this lock guards nothing, and another run may already hold a new file's.
        struct stat now {};
        if (::fstatat(dir->get(), name.c_str(), &now, AT_SYMLINK_NOFOLLOW) != 0 ||
            now.st_ino != held.st_ino || now.st_dev != held.st_dev)
            continue;
        const FileIdentity id{static_cast<std::uint64_t>(held.st_dev),
                              static_cast<std::uint64_t>(held.st_ino)};
        if (!holdsALockOfOurs(fd.get(), now) || inputWithIdentity(id))
            return fileError(target.string(),
                             "the writer's lock " + shown +
                                 " is a file that Parallax Studio did not write; refusing to "
                                 "replace it (rename it, or choose another output)");
        const std::string pid = std::to_string(::getpid()) + "\n";
        if (::ftruncate(fd.get(), 0) == 0) [[maybe_unused]]
            const ssize_t n = ::pwrite(fd.get(), pid.data(), pid.size(), 0);
        noteCreated(id);
        OutputLock lock;
        lock.m_handle = registerTemporary(dir->get(), name);
        lock.m_dir = std::move(*dir);
        lock.m_fd = std::move(fd);
        lock.m_name = name;
        return lock;
    }
    return fileError(target.string(),
                     "cannot take the writer's lock " + shown + ": it keeps being replaced");
}

OutputLock::OutputLock(OutputLock&& other) noexcept
    : m_dir(std::move(other.m_dir)), m_fd(std::move(other.m_fd)), m_name(std::move(other.m_name)),
      m_handle(other.m_handle) {
    other.m_handle = -1;
}

OutputLock::~OutputLock() {
    if (m_fd.get() < 0)
        return;
    releaseTemporary(m_handle);
    discardTemporaryAt(m_dir.get(), m_name); // while still held: see the check after flock()
}

} // namespace px

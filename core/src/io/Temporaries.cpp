#include "parallax/io/Temporaries.h"

#include "parallax/io/Fnv1a.h"
#include "parallax/io/Inputs.h"
#include "parallax/io/OutputGate.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <optional>
#include <string_view>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace px {

namespace fs = std::filesystem;

namespace {

// A fixed table, so that the signal handler reads it without locks or allocation.
enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };
struct Slot {
    std::atomic<int> state{kFree};
    std::atomic<std::uint64_t> order{0};
    int dir = -1, self = -1;
    std::array<char, 64> name{};
};
constexpr int kSlots = 128;
std::array<Slot, kSlots> gSlots;
std::atomic<std::uint64_t> gOrder{1};
std::atomic<int> gDeferDepth{0};
std::atomic<int> gDeferredSignal{0};
TestHooks gHooks;

std::string hex16(std::uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

std::string nameHash(const std::string& name) {
    return hex16(fnv1a(name.data(), name.size()));
}

// Unlinks every entry of the folder open as `fd` (a stage holds only files). Async-signal-safe.
void emptyFolder(int fd) noexcept {
    alignas(8) char buffer[4096];
    for (bool removed = true; removed;) {
        removed = false;
        ::lseek(fd, 0, SEEK_SET);
        const ssize_t n = ::getdents64(fd, buffer, sizeof buffer);
        for (ssize_t at = 0; at < n;) {
            const auto* entry = reinterpret_cast<const struct dirent64*>(buffer + at);
            const char* name = entry->d_name;
            if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0)
                removed = ::unlinkat(fd, name, 0) == 0 || removed;
            at += entry->d_reclen;
        }
    }
}

bool sameInode(const struct stat& a, const struct stat& b) {
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

bool isInput(const struct stat& st) {
    return inputWithIdentity(
               {static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)})
        .has_value();
}

// Why a leftover entry `st` is not what a writer makes ("" when it is a regular file of ours).
std::string notOurs(const struct stat& st) {
    if (!S_ISREG(st.st_mode))
        return fileKind(st.st_mode) + ", which no writer makes";
    if (st.st_uid != ::geteuid())
        return "a file of another user";
    if (st.st_nlink != 1)
        return "a file with other links";
    if (isInput(st))
        return "an input of this run";
    return {};
}

void leaveAlone(const std::string& name, const std::string& why) {
    std::fprintf(stderr, "note: %s: left alone, not provably a dead run's leftover (%s)\n",
                 name.c_str(), why.c_str());
}

// The entries of the folder open as `fd`, read through a duplicate (the fd keeps its offset).
std::vector<std::string> namesIn(int fd) {
    std::vector<std::string> names;
    if (DIR* list = ::fdopendir(::dup(fd))) {
        ::rewinddir(list);
        while (const dirent* e = ::readdir(list)) {
            if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0)
                names.emplace_back(e->d_name);
        }
        ::closedir(list);
    }
    return names;
}

// Removes the leftover `name` in `dir` (a stage, or a file) if it is provably a dead writer's
// (see the header): its lock free, its owner us, nothing in it that a writer does not make.
bool removeIfDead(int dir, const std::string& name, bool stage) {
    struct stat st {};
    if (::fstatat(dir, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0)
        return false;
    const std::string why = !stage                     ? notOurs(st)
                            : !S_ISDIR(st.st_mode)     ? fileKind(st.st_mode) + " for a folder"
                            : st.st_uid != ::geteuid() ? std::string("a folder of another user")
                                                       : std::string();
    if (!why.empty()) {
        leaveAlone(name, why);
        return false;
    }
    const int flags = O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | (stage ? O_DIRECTORY : 0);
    const int fd = ::openat(dir, name.c_str(), flags);
    if (fd < 0)
        return false;
    struct stat opened {};
    bool dead = ::fstat(fd, &opened) == 0 && sameInode(st, opened) &&
                ::flock(fd, LOCK_EX | LOCK_NB) == 0; // a live writer holds it shared
    // Every entry checked through the opened folder: a link or a folder swapped in can only make
    // this leave the stage alone, and removal unlinks names in it, never following one.
    for (const std::string& entry : dead&& stage ? namesIn(fd) : std::vector<std::string>{}) {
        struct stat in {};
        if (::fstatat(fd, entry.c_str(), &in, AT_SYMLINK_NOFOLLOW) != 0)
            continue;
        if (const std::string not_ours = notOurs(in); !not_ours.empty()) {
            leaveAlone(name, "it holds " + entry + ", " + not_ours);
            dead = false;
            break;
        }
    }
    if (dead && stage)
        emptyFolder(fd);
    struct stat now {};
    if (dead && ::fstatat(dir, name.c_str(), &now, AT_SYMLINK_NOFOLLOW) == 0 && sameInode(now, st))
        dead = ::unlinkat(dir, name.c_str(), stage ? AT_REMOVEDIR : 0) == 0;
    ::close(fd);
    return dead;
}

} // namespace

std::string temporaryName(const std::string& name, const char* kind) {
    if (std::string_view(kind) == "lock")
        return ".px-lock-" + nameHash(name);
    std::uint64_t random = 0;
    if (::getrandom(&random, sizeof random, 0) != static_cast<ssize_t>(sizeof random)) {
        static std::atomic<std::uint64_t> counter{0};
        random = (static_cast<std::uint64_t>(::getpid()) << 32) ^ counter++;
    }
    return std::string(".px-") + kind + "-" + nameHash(name) + "-" + hex16(random);
}

void holdTemporary(int fd) {
    while (::flock(fd, LOCK_SH) != 0 && errno == EINTR) {
    }
}

int registerTemporary(int dir, const std::string& name, int self) {
    if (dir < 0 || name.size() >= gSlots[0].name.size())
        return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!gSlots[i].state.compare_exchange_strong(expected, kFilling))
            continue;
        std::memcpy(gSlots[i].name.data(), name.c_str(), name.size() + 1);
        gSlots[i].dir = dir;
        gSlots[i].self = self;
        gSlots[i].order.store(gOrder.fetch_add(1));
        gSlots[i].state.store(kReady);
        return i;
    }
    return -1;
}

void releaseTemporary(int handle) {
    if (handle >= 0 && handle < kSlots)
        gSlots[handle].state.store(kFree);
}

void removeTemporariesNow() noexcept {
    std::uint64_t below = UINT64_MAX; // newest first
    for (;;) {
        int newest = -1;
        std::uint64_t best = 0;
        for (int i = 0; i < kSlots; ++i) {
            const std::uint64_t order = gSlots[i].order.load();
            if (gSlots[i].state.load() == kReady && order < below && order > best) {
                best = order;
                newest = i;
            }
        }
        if (newest < 0)
            return;
        below = best;
        const Slot& slot = gSlots[newest];
        if (slot.self >= 0)
            emptyFolder(slot.self);
        ::unlinkat(slot.dir, slot.name.data(), slot.self >= 0 ? AT_REMOVEDIR : 0);
    }
}

int removeStaleTemporaries(int dir, const std::string& name) {
    const std::string hash = nameHash(name);
    std::vector<std::pair<std::string, bool>> found; // name, stage
    for (const std::string& entry : namesIn(dir)) {
        for (const bool stage : {false, true}) {
            const std::string prefix =
                std::string(".px-") + (stage ? "stage-" : "tmp-") + hash + "-";
            if (entry.size() == prefix.size() + 16 && entry.starts_with(prefix) &&
                entry.find_first_not_of("0123456789abcdef", prefix.size()) == std::string::npos)
                found.emplace_back(entry, stage);
        }
    }
    int removed = 0;
    for (const auto& [entry, stage] : found)
        removed += removeIfDead(dir, entry, stage) ? 1 : 0;
    return removed;
}

int removeStaleTemporaries(const fs::path& target) {
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0)
        return 0;
    const int removed = removeStaleTemporaries(dir, target.filename().string());
    ::close(dir);
    return removed;
}

bool deferInterrupt(int signal) noexcept {
    if (gDeferDepth.load() == 0)
        return false;
    gDeferredSignal.store(signal);
    return true;
}

InterruptDeferral::InterruptDeferral() {
    gDeferDepth.fetch_add(1);
}

InterruptDeferral::~InterruptDeferral() {
    if (gDeferDepth.fetch_sub(1) == 1) {
        if (const int signal = gDeferredSignal.exchange(0); signal != 0)
            std::raise(signal);
    }
}

void setTestHooks(const TestHooks& hooks) {
    gHooks = hooks;
}

const TestHooks& testHooks() {
    return gHooks;
}

void testInterruptPoint(const char* point) {
    if (gHooks.reached != nullptr && point != nullptr && *point != '\0')
        gHooks.reached(point);
}

void discardTemporaryAt(int dir, const std::string& name) {
    const int fd = ::openat(dir, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
        ::unlinkat(dir, name.c_str(), 0); // a file (or nothing)
        return;
    }
    emptyFolder(fd);
    ::close(fd);
    ::unlinkat(dir, name.c_str(), AT_REMOVEDIR);
}

TemporaryGuard::TemporaryGuard(const fs::path& path) {
    const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    m_dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    m_handle = registerTemporary(m_dir, path.filename().string());
}

TemporaryGuard::~TemporaryGuard() {
    releaseTemporary(m_handle);
    if (m_dir >= 0)
        ::close(m_dir);
}

} // namespace px

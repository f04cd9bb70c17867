#include "parallax/io/Temporaries.h"

#include "parallax/io/Fnv1a.h"
#include "parallax/io/OutputGate.h"
#include "parallax/io/StagedSet.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <optional>
#include <string>
#include <string_view>
#include <sys/file.h>
#include <sys/stat.h>
#include <system_error>
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
    std::array<char, 4096> path{};
};
constexpr int kSlots = 128;
std::array<Slot, kSlots> gSlots;
std::atomic<std::uint64_t> gOrder{1};
std::atomic<int> gDeferDepth{0};
std::atomic<int> gDeferredSignal{0};

constexpr std::array<std::string_view, 4> kRoles{"tmp", "export-tmp", "set-tmp", "export-old"};

// A leftover's owner as its name gives it: ".NAME.<role><pid>-<n>[.<host>]".
struct Owner {
    long pid = -1;
    std::string host; // empty: a name of an older version, without one
};

bool digits(std::string_view s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
}

// The owner of `entry` if it is a temporary of `name`.
std::optional<Owner> temporaryOwner(const std::string& entry, const std::string& name) {
    const std::string prefix = "." + name + ".";
    if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0)
        return std::nullopt;
    const std::string_view rest = std::string_view(entry).substr(prefix.size());
    // Older versions staged a turntable's frames as ".NAME.tmpPID-N.png".
    const std::string extension = fs::path(name).extension().string();
    for (std::string_view role : kRoles) {
        if (rest.substr(0, role.size()) != role)
            continue;
        const std::string_view tail = rest.substr(role.size());
        const std::size_t dash = tail.find('-');
        if (dash == std::string_view::npos)
            continue;
        const std::string_view pid = tail.substr(0, dash);
        std::string_view n = tail.substr(dash + 1), host;
        if (const std::size_t dot = n.find('.'); dot != std::string_view::npos) {
            host = n.substr(dot + 1);
            n = n.substr(0, dot);
        }
        if (!digits(pid) || !digits(n) || pid.size() >= 10)
            continue;
        const bool hex = host.size() == 8 &&
                         host.find_first_not_of("0123456789abcdef") == std::string_view::npos;
        if (!host.empty() && !hex && "." + std::string(host) != extension)
            continue;
        return Owner{std::stol(std::string(pid)), hex ? std::string(host) : std::string()};
    }
    return std::nullopt;
}

bool running(long pid) {
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
}

// Whether a writer, anywhere, holds its lock on `entry` (an error counts as held: not provably
// dead). A symbolic link is never one of ours.
bool lockHeld(const fs::path& entry) {
    const int fd = ::open(entry.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0)
        return true;
    const bool held = ::flock(fd, LOCK_EX | LOCK_NB) != 0;
    ::close(fd);
    return held;
}

// Seconds since `entry` last changed.
double age(const fs::path& entry) {
    struct stat st {};
    if (::lstat(entry.c_str(), &st) != 0)
        return 0.0;
    return std::difftime(std::time(nullptr), st.st_mtime);
}

constexpr double kBeyondDoubtSeconds = 3600.0;

bool provablyDead(const fs::path& entry, const Owner& owner) {
    if (lockHeld(entry))
        return false;
    if (owner.host == hostToken())
        return owner.pid != ::getpid() && !running(owner.pid);
    return age(entry) > kBeyondDoubtSeconds;
}

} // namespace

fs::path temporarySibling(const fs::path& target, std::string_view role) {
    static std::atomic<unsigned> counter{0};
    return target.parent_path() /
           ("." + target.filename().string() + "." + std::string(role) +
            std::to_string(::getpid()) + "-" + std::to_string(counter++) + "." + hostToken());
}

void holdTemporary(int fd) {
    while (::flock(fd, LOCK_SH) != 0 && errno == EINTR) {
    }
}

const std::string& hostToken() {
    static const std::string token = [] {
        std::string id;
        if (const int fd = ::open("/proc/sys/kernel/random/boot_id", O_RDONLY | O_CLOEXEC);
            fd >= 0) {
            char text[64] = {};
            const ssize_t n = ::read(fd, text, sizeof text);
            id.assign(text, n > 0 ? static_cast<std::size_t>(n) : 0);
            ::close(fd);
        }
        char ns[64] = {};
        const ssize_t n = ::readlink("/proc/self/ns/pid", ns, sizeof ns);
        id.append(ns, n > 0 ? static_cast<std::size_t>(n) : 0);
        const std::uint64_t h = fnv1a(id.data(), id.size());
        char hex[9];
        std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(h ^ (h >> 32)));
        return std::string(hex);
    }();
    return token;
}

int registerTemporary(const fs::path& path) {
    const std::string text = path.string();
    if (text.size() >= gSlots[0].path.size())
        return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!gSlots[i].state.compare_exchange_strong(expected, kFilling))
            continue;
        std::memcpy(gSlots[i].path.data(), text.c_str(), text.size() + 1);
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
    // Newest first: the files of a staging folder were registered after the folder.
    std::uint64_t below = UINT64_MAX;
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
        const char* path = gSlots[newest].path.data();
        // A folder: Linux reports EISDIR, POSIX allows EPERM.
        if (::unlink(path) != 0 && (errno == EISDIR || errno == EPERM))
            ::rmdir(path);
    }
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

void testInterruptPoint(const char* point) {
    static std::atomic<bool> fired{false};
    const char* spec = std::getenv("PX_TEST_RAISE"); // read each time: a forked test sets it
    if (spec == nullptr || fired.load())
        return;
    const std::string_view text(spec);
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos || text.substr(colon + 1) != point)
        return;
    const std::string_view name = text.substr(0, colon);
    const int signal = name == "TERM"   ? SIGTERM
                       : name == "KILL" ? SIGKILL
                       : name == "STOP" ? SIGSTOP
                       : name == "HUP"  ? SIGHUP
                                        : SIGINT;
    fired.store(true); // once
    std::raise(signal);
}

int removeStaleTemporaries(const fs::path& target) {
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const std::string name = target.filename().string();
    if (name.empty())
        return 0;
    std::vector<fs::path> dead;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::optional<Owner> owner = temporaryOwner(it->path().filename().string(), name);
        if (owner && provablyDead(it->path(), *owner))
            dead.push_back(it->path());
    }
    int removed = 0;
    for (const fs::path& entry : dead) {
        if (finishCommittedStage(entry) || removeOwned(entry, Removal::Leftover))
            ++removed;
    }
    return removed;
}

} // namespace px

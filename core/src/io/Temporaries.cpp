#include "parallax/io/Temporaries.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>
#include <unistd.h>

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

constexpr std::array<std::string_view, 3> kRoles{"tmp", "export-tmp", "export-old"};

// The pid in ".NAME.<role><pid>-<n>", or -1 if `entry` is not a temporary of `name`.
long temporaryOwner(const std::string& entry, const std::string& name) {
    const std::string prefix = "." + name + ".";
    if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0)
        return -1;
    const std::string_view rest = std::string_view(entry).substr(prefix.size());
    for (std::string_view role : kRoles) {
        if (rest.substr(0, role.size()) != role)
            continue;
        const std::string_view tail = rest.substr(role.size());
        const std::size_t dash = tail.find('-');
        if (dash == 0 || dash == std::string_view::npos || dash + 1 == tail.size())
            continue;
        const std::string_view pid = tail.substr(0, dash), n = tail.substr(dash + 1);
        auto digits = [](std::string_view s) {
            return s.find_first_not_of("0123456789") == std::string_view::npos;
        };
        if (digits(pid) && digits(n) && pid.size() < 10)
            return std::stol(std::string(pid));
    }
    return -1;
}

bool running(long pid) {
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
}

} // namespace

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
    static const char* spec = std::getenv("PX_TEST_RAISE");
    if (spec == nullptr)
        return;
    const std::string_view text(spec);
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos || text.substr(colon + 1) != point)
        return;
    const std::string_view name = text.substr(0, colon);
    const int signal = name == "TERM" ? SIGTERM : name == "KILL" ? SIGKILL : SIGINT;
    spec = nullptr; // once
    std::raise(signal);
}

int removeStaleTemporaries(const fs::path& target) {
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const std::string name = target.filename().string();
    if (name.empty())
        return 0;
    int removed = 0;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const long pid = temporaryOwner(it->path().filename().string(), name);
        if (pid <= 0 || pid == ::getpid() || running(pid))
            continue;
        std::error_code ignored;
        if (fs::remove_all(it->path(), ignored) > 0)
            ++removed;
    }
    return removed;
}

} // namespace px

#include "ImageBudget.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <sys/resource.h>
#include <unistd.h>

namespace px {
namespace {

std::string gigabytes(std::int64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GB", static_cast<double>(bytes) / 1e9);
    return text;
}

// The first number in a file ("max" and unreadable files give nullopt).
std::optional<std::int64_t> numberIn(const std::string& file) {
    std::ifstream in(file);
    long long value = 0;
    if (in >> value)
        return static_cast<std::int64_t>(value);
    return std::nullopt;
}

std::optional<std::int64_t> meminfoAvailable() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key, unit;
    long long kb = 0;
    while (meminfo >> key >> kb >> unit)
        if (key == "MemAvailable:")
            return static_cast<std::int64_t>(kb) * 1024;
    return std::nullopt;
}

// Room under an rlimit given what the process has now (statm's field, in pages).
std::optional<std::int64_t> rlimitRoom(int resource, int statmField) {
    rlimit limit{};
    if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
        return std::nullopt;
    std::ifstream statm("/proc/self/statm");
    long long pages[7] = {};
    for (long long& p : pages)
        statm >> p;
    const std::int64_t used = pages[statmField] * static_cast<std::int64_t>(sysconf(_SC_PAGESIZE));
    return std::max<std::int64_t>(1,
                                  static_cast<std::int64_t>(limit.rlim_cur) - used); // 0: unknown
}

// The least room left under the memory limit of this process's cgroup and each one above it.
std::optional<std::int64_t> cgroupRoom() {
    std::ifstream self("/proc/self/cgroup");
    std::optional<std::int64_t> room;
    auto consider = [&room](const std::string& limitFile, const std::string& usageFile) {
        const std::optional<std::int64_t> limit = numberIn(limitFile);
        const std::optional<std::int64_t> usage = numberIn(usageFile);
        if (limit && usage && *limit < (std::int64_t{1} << 60))
            room = std::min(room.value_or(*limit), std::max<std::int64_t>(1, *limit - *usage));
    };
    std::string line;
    while (std::getline(self, line)) {
        const bool v2 = line.rfind("0::", 0) == 0;
        const std::size_t memory = line.find(":memory:");
        if (!v2 && memory == std::string::npos)
            continue;
        std::string group = v2 ? line.substr(3) : line.substr(memory + 8);
        const std::string root = v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory";
        for (;;) {
            const std::string dir = root + (group == "/" ? "" : group);
            if (v2)
                consider(dir + "/memory.max", dir + "/memory.current");
            else
                consider(dir + "/memory.limit_in_bytes", dir + "/memory.usage_in_bytes");
            const std::size_t slash = group.find_last_of('/');
            if (group.empty() || group == "/" || slash == std::string::npos)
                break;
            group = slash == 0 ? "/" : group.substr(0, slash);
        }
    }
    return room;
}

} // namespace

std::int64_t memoryHeadroomBytes() {
    std::optional<std::int64_t> room = meminfoAvailable();
    for (const std::optional<std::int64_t> other :
         {rlimitRoom(RLIMIT_AS, 0), rlimitRoom(RLIMIT_DATA, 5), cgroupRoom()}) {
        if (other)
            room = std::min(room.value_or(*other), *other);
    }
    return room.value_or(0);
}

Status checkImageClaim(const std::string& path, const ImageClaim& claim) {
    const std::string size = std::to_string(claim.width) + "x" + std::to_string(claim.height);
    if (claim.minFileBytes > 0 && claim.fileBytes > 0 && claim.minFileBytes > claim.fileBytes)
        return fileError(path, "the header claims " + size + " texels, which a file of " +
                                   std::to_string(claim.fileBytes) +
                                   " bytes cannot hold (at least " +
                                   std::to_string(claim.minFileBytes) +
                                   " are needed): the file is damaged or truncated");
    // The float copy readImage makes; loaders make at most one more of a channel.
    const std::int64_t needed = claim.width * claim.height * (claim.channels + 1) * 4;
    const std::int64_t room = memoryHeadroomBytes();
    if (room > 0 && needed > room)
        return fileError(path, "the image is " + size + " texels and needs " + gigabytes(needed) +
                                   " of memory to read, more than the " + gigabytes(room) +
                                   " available to this process");
    return success();
}

} // namespace px

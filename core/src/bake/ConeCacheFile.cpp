#include "ConeCacheFile.h"

#include "parallax/Version.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Fnv1a.h"
#include "parallax/io/Inputs.h"
#include "parallax/io/OutputGate.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

namespace px {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'P', 'X', 'C', 'O', 'N', 'E', '0', '1'};
constexpr const char* kSuffix = ".pxcone";

// The header, as written (little-endian hosts: the project's platforms are).
struct Header {
    char magic[8];
    std::uint64_t content;
    std::int32_t width, height, wrap, kind;
    std::uint64_t baker;
    std::uint64_t payload; // FNV-1a of the texels' bytes
};

Header headerFor(const ConeCacheKey& key) {
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.content = key.content;
    h.width = key.width;
    h.height = key.height;
    h.wrap = static_cast<std::int32_t>(key.wrap);
    h.kind = static_cast<std::int32_t>(key.kind);
    h.baker = coneBakerFingerprint();
    return h;
}

bool sameKey(const Header& a, const Header& b) {
    return std::memcmp(a.magic, b.magic, sizeof a.magic) == 0 && a.content == b.content &&
           a.width == b.width && a.height == b.height && a.wrap == b.wrap && a.kind == b.kind &&
           a.baker == b.baker;
}

// Removes the oldest of this cache's files (by last use) while they take more than `limit`.
void trim(const fs::path& dir, std::uint64_t limit) {
    std::error_code ec;
    struct Entry {
        fs::path path;
        fs::file_time_type used;
        std::uint64_t bytes;
    };
    std::vector<Entry> entries;
    std::uint64_t total = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("cone-", 0) != 0 || e.path().extension() != kSuffix ||
            !e.is_regular_file(ec))
            continue;
        const std::uint64_t bytes = e.file_size(ec);
        entries.push_back({e.path(), e.last_write_time(ec), bytes});
        total += bytes;
    }
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.used < b.used; });
    for (const Entry& e : entries) {
        if (total <= limit)
            break;
        if (removeOwned(e.path))
            total -= e.bytes;
    }
}

} // namespace

fs::path coneCachePath(const fs::path& dir, const ConeCacheKey& key) {
    char name[128];
    std::snprintf(name, sizeof name, "cone-%016llx-%dx%d-%s-%s-%016llx%s",
                  static_cast<unsigned long long>(key.content), key.width, key.height,
                  std::string(toString(key.wrap)).c_str(),
                  key.kind == ConeKind::Relaxed ? "relaxed" : "conservative",
                  static_cast<unsigned long long>(coneBakerFingerprint()), kSuffix);
    return dir / name;
}

Result<std::optional<ConeMap>> readCachedCone(const fs::path& dir, const ConeCacheKey& key) {
    const fs::path path = coneCachePath(dir, key);
    // Opened without blocking (a FIFO in the cache must not hang the run), recorded as an input
    // only once its content is used: a damaged file is replaced by the next write.
    Result<InputFile> in = InputFile::open(path.string(), "a cached cone map", false);
    if (!in || key.width <= 0 || key.height <= 0)
        return std::optional<ConeMap>();
    Header found{};
    const Header wanted = headerFor(key);
    ConeMap map(key.kind, key.width, key.height);
    const std::size_t bytes = map.sqrtRatio.size() * sizeof(float);
    if (in->size() != sizeof found + bytes || !in->readAt(0, &found, sizeof found) ||
        !sameKey(found, wanted) || !in->readAt(sizeof found, map.sqrtRatio.data(), bytes) ||
        fnv1a(map.sqrtRatio.data(), bytes) != found.payload)
        return std::optional<ConeMap>();
    // A good entry is an input like any other: an output of this run naming it is refused.
    if (Status s = in->record("a cached cone map"); !s)
        return s.error();
    std::error_code ec;
    fs::last_write_time(path, fs::file_time_type::clock::now(), ec); // its last use, for trim
    return std::optional<ConeMap>(std::move(map));
}

Status writeCachedCone(const fs::path& dir, const ConeCacheKey& key, const ConeMap& map,
                       std::uint64_t limitBytes) {
    if (map.width != key.width || map.height != key.height)
        return Error{"the cone map's size differs from the height map's"};
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        return fileError(dir.string(), ec.message());
    Header h = headerFor(key);
    const std::size_t bytes = map.sqrtRatio.size() * sizeof(float);
    h.payload = fnv1a(map.sqrtRatio.data(), bytes);
    std::string contents(sizeof h + bytes, '\0');
    std::memcpy(contents.data(), &h, sizeof h);
    std::memcpy(contents.data() + sizeof h, map.sqrtRatio.data(), bytes);
    if (Status s = writeFileAtomically(coneCachePath(dir, key).string(), contents); !s)
        return s; // best effort: the bake is in hand
    trim(dir, limitBytes);
    return success();
}

std::uint64_t coneBakerFingerprint() {
    static const std::uint64_t fingerprint = [] {
        // A small map with what the bakers treat specially: a wall, a pit, a spike, slopes, a
        // long flat ending in a spike, a patch of hashed noise. Many tiles and pyramid levels wide,
        // so that a change that only shows past one tile or level still changes the fingerprint
        // (about 20 ms, once a process).
        HeightField field(48, 40);
        for (int y = 0; y < field.height; ++y)
            for (int x = 0; x < field.width; ++x) {
                const unsigned mix = unsigned(x) * 73856093U ^ unsigned(y) * 19349663U;
                float h = 0.3f + 0.02f * float((x * 7 + y * 13) % 11);
                h = (x >= 40 && y < 8) ? 0.1f + 0.8f * float(mix % 1000U) / 1000.0f : h;
                h = x == 24 ? 0.9f : h;
                h = (x == 5 && y == 6) ? 1.0f : h;
                h = (x >= 9 && x <= 11 && y >= 12 && y <= 14) ? 0.0f : h;
                h = (y >= 30 && x < 40) ? (x == 39 ? 1.0f : 0.2f) : h;
                field.at(x, y) = h;
            }
        std::uint64_t h = fnv1a(kVersion, std::strlen(kVersion));
        for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp})
            for (ConeKind kind : {ConeKind::Conservative, ConeKind::Relaxed}) {
                const ConeMap cone = bakeConeMap(field, wrap, kind);
                h = fnv1a(cone.sqrtRatio.data(), cone.sqrtRatio.size() * sizeof(float), h);
            }
        return h;
    }();
    return fingerprint;
}

} // namespace px

#pragma once
// Baked cone maps kept on disk between runs of `recommend` (the bakes are most of a cold
// recommendation: bricks 2048² took 16.9 s of CPU cold, 3.7 s with the maps supplied). A file holds
// one map, named and headed by what the bake depends on: the height map's content hash and size,
// the wrap, the kind, and the baker's fingerprint (its output on a small fixed map, with the
// project's version), so a changed baker never reads an old bake. Reading checks the header and a
// hash of the payload; a damaged or foreign file is ignored (and replaced by the next write).
// Writing is atomic and best effort: a cache that cannot be written costs time, never the answer.

#include "parallax/Result.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/WrapMode.h"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace px {

struct ConeCacheKey {
    std::uint64_t content = 0; // the height map's texels (FNV-1a)
    int width = 0, height = 0;
    WrapMode wrap = WrapMode::Repeat;
    ConeKind kind = ConeKind::Conservative;
};

// The file `key`'s map has (or would have) in `dir`.
std::filesystem::path coneCachePath(const std::filesystem::path& dir, const ConeCacheKey& key);

// The map, or nothing when absent, damaged or written by another baker; an error when the entry
// is a file this run means to write (Inputs.h: planOutput).
Result<std::optional<ConeMap>> readCachedCone(const std::filesystem::path& dir,
                                              const ConeCacheKey& key);

// Writes `map` for `key` (creating `dir`), then removes this cache's oldest files (by their last
// use) while its files take more than `limitBytes`. Never touches a file it did not name. An
// error (the folder cannot be made or written) says why nothing was kept; the caller carries on.
Status writeCachedCone(const std::filesystem::path& dir, const ConeCacheKey& key,
                       const ConeMap& map, std::uint64_t limitBytes);

// What identifies the bakers' output: a hash of both kinds baked on a small fixed map, and the
// project's version.
std::uint64_t coneBakerFingerprint();

} // namespace px

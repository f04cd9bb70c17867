#pragma once
// FNV-1a over bytes: the project's content keys and file checksums (a map's texels, a cached
// bake's payload, a preview's cost key). Not cryptographic: it tells data apart, it does not
// defend against a forger. Chain calls by passing the last result as `h`.

#include <cstddef>
#include <cstdint>

namespace px {

inline constexpr std::uint64_t kFnv1aOffset = 0xcbf29ce484222325ULL;

inline std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t h = kFnv1aOffset) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) {
        h ^= p[k];
        h *= 0x100000001b3ULL;
    }
    return h;
}

} // namespace px

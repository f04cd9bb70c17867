#pragma once
// How texel indices outside the map are resolved (docs/conventions.md §1). A material property:
// every CPU sampler, baker and GPU sampler of a material uses the same mode.

#include <optional>
#include <string_view>

namespace px {

enum class WrapMode { Repeat, Clamp };

constexpr std::string_view toString(WrapMode mode) {
    return mode == WrapMode::Repeat ? "repeat" : "clamp";
}

constexpr std::optional<WrapMode> parseWrapMode(std::string_view name) {
    if (name == "repeat")
        return WrapMode::Repeat;
    if (name == "clamp")
        return WrapMode::Clamp;
    return std::nullopt;
}

// Resolves an integer texel index against a side of `size` texels.
constexpr int wrapIndex(int i, int size, WrapMode mode) {
    if (mode == WrapMode::Clamp)
        return i < 0 ? 0 : (i >= size ? size - 1 : i);
    const int r = i % size;
    return r < 0 ? r + size : r;
}

} // namespace px

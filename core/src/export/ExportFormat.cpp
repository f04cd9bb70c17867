#include "parallax/export/ExportFormat.h"

#include <array>

namespace px {
namespace {

constexpr std::array<std::string_view, 5> kNames{"package", "gltf", "godot", "unreal", "unity"};

} // namespace

std::string_view toString(ExportFormat format) {
    return kNames[static_cast<int>(format)];
}

std::optional<ExportFormat> parseExportFormat(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i) {
        if (kNames[i] == name)
            return static_cast<ExportFormat>(i);
    }
    return std::nullopt;
}

std::span<const std::string_view> exportFormatNames() {
    return kNames;
}

} // namespace px

#include "parallax/material/MaterialNames.h"

#include <array>
#include <cstddef>

namespace px {
namespace {

// Index i of each table is the enum value i.
// Normal sources have two spellings: the material file's, and the short one of the command line
// and of shader variant names.
struct NormalSourceSpelling {
    std::string_view file;
    std::string_view shortName;
};
constexpr std::array<NormalSourceSpelling, 4> kNormalSourceSpellings{
    {{"none", "none"}, {"map", "map"}, {"height-central", "central"}, {"height-sobel", "sobel"}}};
template <std::string_view NormalSourceSpelling::*Member>
constexpr std::array<std::string_view, kNormalSourceSpellings.size()> spellingColumn() {
    std::array<std::string_view, kNormalSourceSpellings.size()> column{};
    for (std::size_t i = 0; i < column.size(); ++i)
        column[i] = kNormalSourceSpellings[i].*Member;
    return column;
}
constexpr auto kNormalSources = spellingColumn<&NormalSourceSpelling::file>();
constexpr auto kNormalSourceShortNames = spellingColumn<&NormalSourceSpelling::shortName>();
constexpr std::array<std::string_view, 2> kNormalGreens{"opengl", "directx"};
constexpr std::array<std::string_view, 2> kLightingModels{"blinn-phong", "metallic-roughness"};
constexpr std::array<std::string_view, 5> kHeightChannels{"red", "green", "blue", "alpha",
                                                          "luminance"};

template <typename Enum, std::size_t N>
std::optional<Enum> find(const std::array<std::string_view, N>& table, std::string_view name) {
    for (std::size_t i = 0; i < N; ++i) {
        if (table[i] == name)
            return static_cast<Enum>(i);
    }
    return std::nullopt;
}

template <std::size_t N>
std::string_view nameAt(const std::array<std::string_view, N>& table, int index) {
    return index >= 0 && static_cast<std::size_t>(index) < N ? table[index] : "?";
}

} // namespace

std::string_view toString(NormalSource source) {
    return nameAt(kNormalSources, static_cast<int>(source));
}
std::string_view shortName(NormalSource source) {
    return nameAt(kNormalSourceShortNames, static_cast<int>(source));
}
std::string_view toString(NormalGreen green) {
    return nameAt(kNormalGreens, static_cast<int>(green));
}
std::string_view toString(LightingModel model) {
    return nameAt(kLightingModels, static_cast<int>(model));
}
std::string_view toString(HeightChannel channel) {
    return nameAt(kHeightChannels, static_cast<int>(channel));
}

std::optional<NormalSource> parseNormalSource(std::string_view name) {
    return find<NormalSource>(kNormalSources, name);
}
std::optional<NormalSource> parseNormalSourceShortName(std::string_view name) {
    return find<NormalSource>(kNormalSourceShortNames, name);
}
std::optional<NormalGreen> parseNormalGreen(std::string_view name) {
    return find<NormalGreen>(kNormalGreens, name);
}
std::optional<LightingModel> parseLightingModel(std::string_view name) {
    return find<LightingModel>(kLightingModels, name);
}

std::span<const std::string_view> normalSourceNames() {
    return kNormalSources;
}
std::span<const std::string_view> normalSourceShortNames() {
    return kNormalSourceShortNames;
}
std::span<const std::string_view> normalGreenNames() {
    return kNormalGreens;
}
std::span<const std::string_view> lightingModelNames() {
    return kLightingModels;
}
std::span<const std::string_view> heightChannelNames() {
    return kHeightChannels;
}

} // namespace px

#pragma once
// The names the material file, the command line, the editor and the shader variants use for a
// material's enums. One table per enum so a name is spelled the same everywhere.

#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/material/Material.h"

#include <optional>
#include <span>
#include <string_view>

namespace px {

std::string_view toString(NormalSource source);   // "none", "map", "height-central", "height-sobel"
std::string_view toString(NormalGreen green);     // "opengl", "directx"
std::string_view toString(LightingModel model);   // "blinn-phong", "metallic-roughness"
std::string_view toString(HeightChannel channel); // "red", "green", "blue", "alpha", "luminance"

std::optional<NormalSource> parseNormalSource(std::string_view name);
std::optional<NormalGreen> parseNormalGreen(std::string_view name);
std::optional<LightingModel> parseLightingModel(std::string_view name);
// parseHeightChannel is in HeightFieldLoader.h (it also accepts "r", "luma", ...).

std::span<const std::string_view> normalSourceNames();

// The short spelling of a normal source, used by the command line (--normal-source) and in shader
// variant names: "none", "map", "central", "sobel".
std::string_view shortName(NormalSource source);
std::optional<NormalSource> parseNormalSourceShortName(std::string_view name);
std::span<const std::string_view> normalSourceShortNames();

std::span<const std::string_view> normalGreenNames();
std::span<const std::string_view> lightingModelNames();
std::span<const std::string_view> heightChannelNames();

} // namespace px

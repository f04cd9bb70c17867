#pragma once
// Where an export is headed: the project's own package, or an engine's conventions.

#include "parallax/material/Material.h"

#include <optional>
#include <span>
#include <string_view>

namespace px {

enum class ExportFormat {
    Package, // material JSON, the maps the technique reads, the specialised fragment shader
    Gltf,    // glTF 2.0: a plane, a metallic-roughness material, height parameters in extras
    Godot,   // a Godot 4 StandardMaterial3D .tres with its textures
    Unreal,  // textures as Unreal expects them (DirectX green, ORM packing) and a settings note
    Unity,   // textures as Unity expects them (OpenGL green, metallic-smoothness) and a note
};

std::string_view toString(ExportFormat format); // "package", "gltf", "godot", "unreal", "unity"
std::optional<ExportFormat> parseExportFormat(std::string_view name);
std::span<const std::string_view> exportFormatNames();

} // namespace px

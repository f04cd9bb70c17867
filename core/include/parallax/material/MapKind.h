#pragma once
// The maps a material can hold, as the editor and the import list them, and how files are
// recognised as one of them by their suffix (docs/conventions.md §6).

#include "parallax/material/Material.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace px {

enum class MapKind { Albedo, Height, Normal, Cone, RelaxedCone, Ao, Roughness, Metallic };

inline constexpr std::array<MapKind, 8> kAllMapKinds{
    MapKind::Albedo,      MapKind::Height, MapKind::Normal,    MapKind::Cone,
    MapKind::RelaxedCone, MapKind::Ao,     MapKind::Roughness, MapKind::Metallic};

std::string_view mapKey(MapKind kind);   // "albedo", "relaxed-cone": file names and settings
std::string_view mapTitle(MapKind kind); // "Relaxed cone map": for people

std::string& mapPath(MaterialMaps& maps, MapKind kind);
const std::string& mapPath(const MaterialMaps& maps, MapKind kind);

// What a file name's suffix says it holds: "wall_disp.png" is a height map, "wall_depth.exr" a
// depth map (height, white = deep). Case-insensitive; the extension is ignored.
struct SuffixMatch {
    MapKind kind;
    bool depth = false;  // white = deep: load inverted
    std::string setName; // the name without its suffix ("wall" for "wall_disp"); may be empty
};
std::optional<SuffixMatch> mapKindFromFileName(const std::string& fileName);

// True for extensions the image reader handles (png, jpg, tif, exr, bmp, tga, hdr).
bool isImageFileName(const std::string& fileName);

} // namespace px

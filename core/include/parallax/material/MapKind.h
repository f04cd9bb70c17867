#pragma once
// The maps a material can hold, as the editor and the import list them, and how files are
// recognised as one of them by their name (MapFileName.h, docs/texture-sets.md).

#include "parallax/material/Material.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace px {

enum class MapKind { Albedo, Height, Normal, Cone, RelaxedCone, Ao, Roughness, Metallic, Specular };

inline constexpr std::array<MapKind, 9> kAllMapKinds{
    MapKind::Albedo, MapKind::Height,    MapKind::Normal,   MapKind::Cone,    MapKind::RelaxedCone,
    MapKind::Ao,     MapKind::Roughness, MapKind::Metallic, MapKind::Specular};

std::string_view mapKey(MapKind kind);   // "albedo", "relaxed-cone": file names and settings
std::string_view mapTitle(MapKind kind); // "Relaxed cone map": for people

std::string& mapPath(MaterialMaps& maps, MapKind kind);
const std::string& mapPath(const MaterialMaps& maps, MapKind kind);

// What a file name's tag says it holds, for one file loaded on its own: "wall_disp.png" is a height
// map, "wall_depth.exr" a depth map (height, white = deep), "Wall_NormalGL_2K.png" a normal map.
// Tags that need a set's import (packed maps, gloss, glued tags) give nothing here.
struct SuffixMatch {
    MapKind kind;
    bool depth = false;  // white = deep: load inverted
    std::string setName; // the name without its tag ("wall" for "wall_disp"); may be empty
};
std::optional<SuffixMatch> mapKindFromFileName(const std::string& fileName);

// True for extensions the image reader handles (png, jpg, tif, exr, bmp, tga, hdr).
bool isImageFileName(const std::string& fileName);

} // namespace px

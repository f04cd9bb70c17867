#include "parallax/material/MapKind.h"

#include "parallax/material/MapFileName.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace px {

std::string_view mapKey(MapKind kind) {
    switch (kind) {
    case MapKind::Albedo:
        return "albedo";
    case MapKind::Height:
        return "height";
    case MapKind::Normal:
        return "normal";
    case MapKind::Cone:
        return "cone";
    case MapKind::RelaxedCone:
        return "relaxed-cone";
    case MapKind::Ao:
        return "ao";
    case MapKind::Roughness:
        return "roughness";
    case MapKind::Metallic:
        return "metallic";
    case MapKind::Specular:
        return "specular";
    }
    return "";
}

std::string_view mapTitle(MapKind kind) {
    switch (kind) {
    case MapKind::Albedo:
        return "Albedo";
    case MapKind::Height:
        return "Height";
    case MapKind::Normal:
        return "Normal";
    case MapKind::Cone:
        return "Cone";
    case MapKind::RelaxedCone:
        return "Relaxed cone";
    case MapKind::Ao:
        return "Occlusion";
    case MapKind::Roughness:
        return "Roughness";
    case MapKind::Metallic:
        return "Metallic";
    case MapKind::Specular:
        return "Specular";
    }
    return "";
}

std::string& mapPath(MaterialMaps& maps, MapKind kind) {
    switch (kind) {
    case MapKind::Albedo:
        return maps.albedo;
    case MapKind::Height:
        return maps.height;
    case MapKind::Normal:
        return maps.normal;
    case MapKind::Cone:
        return maps.cone;
    case MapKind::RelaxedCone:
        return maps.relaxedCone;
    case MapKind::Ao:
        return maps.ao;
    case MapKind::Roughness:
        return maps.roughness;
    case MapKind::Metallic:
        return maps.metallic;
    case MapKind::Specular:
        return maps.specular;
    }
    return maps.albedo;
}

const std::string& mapPath(const MaterialMaps& maps, MapKind kind) {
    return mapPath(const_cast<MaterialMaps&>(maps), kind);
}

namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::optional<MapKind> kindOf(MapRole role) {
    switch (role) {
    case MapRole::Albedo:
        return MapKind::Albedo;
    case MapRole::Height:
    case MapRole::Depth:
    case MapRole::Bump:
        return MapKind::Height;
    case MapRole::Normal:
    case MapRole::NormalGloss:
        return MapKind::Normal;
    case MapRole::Roughness:
        return MapKind::Roughness;
    case MapRole::Metallic:
        return MapKind::Metallic;
    case MapRole::Ao:
        return MapKind::Ao;
    case MapRole::Cone:
        return MapKind::Cone;
    case MapRole::RelaxedCone:
        return MapKind::RelaxedCone;
    case MapRole::Specular:
        return MapKind::Specular;
    default:
        return std::nullopt; // packed, inverted or unused: only a set's import reads them
    }
}

} // namespace

std::optional<SuffixMatch> mapKindFromFileName(const std::string& fileName) {
    const NameReading r = readMapFileName(fileName).front();
    if (!r.tag || r.glued)
        return std::nullopt;
    const std::optional<MapKind> kind = kindOf(r.tag->role);
    if (!kind)
        return std::nullopt;
    return SuffixMatch{*kind, r.tag->role == MapRole::Depth, r.stem};
}

bool isImageFileName(const std::string& fileName) {
    const std::string ext = lower(std::filesystem::path(fileName).extension().string());
    for (const char* known :
         {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr", ".bmp", ".tga", ".hdr"}) {
        if (ext == known)
            return true;
    }
    return false;
}

} // namespace px

#include "parallax/material/MapKind.h"

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
    }
    return maps.albedo;
}

const std::string& mapPath(const MaterialMaps& maps, MapKind kind) {
    return mapPath(const_cast<MaterialMaps&>(maps), kind);
}

namespace {

struct Suffix {
    std::string_view text;
    MapKind kind;
    bool depth;
};

// Longest first, so "_relaxed_cone" is not read as "_cone" and "_normal" not as "_n".
constexpr Suffix kSuffixes[] = {
    {"relaxed_cone", MapKind::RelaxedCone, false},
    {"relaxed-cone", MapKind::RelaxedCone, false},
    {"relaxedcone", MapKind::RelaxedCone, false},
    {"displacement", MapKind::Height, false},
    {"basecolour", MapKind::Albedo, false},
    {"base_color", MapKind::Albedo, false},
    {"basecolor", MapKind::Albedo, false},
    {"occlusion", MapKind::Ao, false},
    {"roughness", MapKind::Roughness, false},
    {"metallic", MapKind::Metallic, false},
    {"diffuse", MapKind::Albedo, false},
    {"albedo", MapKind::Albedo, false},
    {"colour", MapKind::Albedo, false},
    {"normal", MapKind::Normal, false},
    {"height", MapKind::Height, false},
    {"color", MapKind::Albedo, false},
    {"depth", MapKind::Height, true},
    {"rcone", MapKind::RelaxedCone, false},
    {"cone", MapKind::Cone, false},
    {"disp", MapKind::Height, false},
    {"nrm", MapKind::Normal, false},
    {"ao", MapKind::Ao, false},
    {"n", MapKind::Normal, false},
    {"h", MapKind::Height, false},
};

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

bool isSeparator(char c) {
    return c == '_' || c == '-' || c == '.' || c == ' ';
}

} // namespace

std::optional<SuffixMatch> mapKindFromFileName(const std::string& fileName) {
    const std::string original = std::filesystem::path(fileName).stem().string();
    const std::string stem = lower(original);
    for (const Suffix& s : kSuffixes) {
        if (stem.size() < s.text.size() || !stem.ends_with(s.text))
            continue;
        // The suffix must be a whole word: "wall_disp", "disp", not "grasp" for "_sp".
        const std::size_t start = stem.size() - s.text.size();
        if (start == 0 || isSeparator(stem[start - 1]))
            return SuffixMatch{s.kind, s.depth, original.substr(0, start == 0 ? 0 : start - 1)};
    }
    return std::nullopt;
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

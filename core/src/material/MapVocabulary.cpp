#include "parallax/material/MapVocabulary.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace px {

namespace {

constexpr std::string_view kNodeWrangler = "Blender Node Wrangler";

// Longer tags are tried first wherever names are matched, so "bent normal" is not a normal map
// and "mixed ao" not a set named "..._mixed".
constexpr MapTag kTags[] = {
    // Colour.
    {"albedo", MapRole::Albedo, "Node Wrangler, Quixel, Godot"},
    {"diffuse", MapRole::Albedo, "Node Wrangler, LearnOpenGL"},
    {"diff", MapRole::Albedo, "Node Wrangler, Poly Haven, CryEngine"},
    {"dif", MapRole::Albedo, "older texture packs"},
    {"base color", MapRole::Albedo, "Node Wrangler, Substance, glTF"},
    {"basecolor", MapRole::Albedo, "Node Wrangler"},
    {"base colour", MapRole::Albedo, "British spelling"},
    {"basecolour", MapRole::Albedo, "British spelling"},
    {"col", MapRole::Albedo, "Node Wrangler, Poliigon (_COL)"},
    {"color", MapRole::Albedo, "Node Wrangler, ambientCG"},
    {"colour", MapRole::Albedo, "British spelling"},
    {"alb", MapRole::Albedo, "abbreviation"},
    {"d", MapRole::Albedo, "Doom 3 (_d), Unreal naming (T_Name_D)"},
    {"main tex", MapRole::Albedo, "Unity (_MainTex)"},
    {"maintex", MapRole::Albedo, "Unity (_MainTex)"},
    // Relief.
    {"height", MapRole::Height, "Node Wrangler, Substance, Parallax Studio"},
    {"heightmap", MapRole::Height, "Node Wrangler"},
    {"height map", MapRole::Height, "spelled apart"},
    {"hgt", MapRole::Height, "abbreviation"},
    {"h", MapRole::Height, "Doom 3 (_h), Unreal naming (T_Name_H)"},
    {"z", MapRole::Height, "game texture packs (stone01z)"},
    {"displacement", MapRole::Height, "Node Wrangler, ambientCG, Quixel"},
    {"displace", MapRole::Height, "Node Wrangler"},
    {"disp", MapRole::Height, "Node Wrangler, Poly Haven, Poliigon, LearnOpenGL"},
    {"displ", MapRole::Height, "CryEngine (_displ)"},
    {"dsp", MapRole::Height, "Node Wrangler"},
    {"parallax", MapRole::Height, "Unity (_ParallaxMap)"},
    {"depth", MapRole::Depth, "Parallax Studio (white = deep)"},
    {"bump", MapRole::Bump, "Node Wrangler, Poly Haven, Quixel, DarkPlaces"},
    {"bmp", MapRole::Bump, "Node Wrangler"},
    {"bumpmap", MapRole::Bump, "spelled together"},
    // Normals. Alpha is read from the texels: a height (Cube 2/Tesseract _nm, DarkPlaces _norm)
    // or not.
    {"normal", MapRole::Normal, "Node Wrangler, Quixel, Substance"},
    {"normals", MapRole::Normal, "plural"},
    {"normalmap", MapRole::Normal, "spelled together"},
    {"normal map", MapRole::Normal, "spelled apart"},
    {"nor", MapRole::Normal, "Node Wrangler, Poly Haven (_nor_gl, _nor_dx)"},
    {"nrm", MapRole::Normal, "Node Wrangler, Poliigon (_NRM)"},
    {"nrml", MapRole::Normal, "Node Wrangler"},
    {"norm", MapRole::Normal, "Node Wrangler, DarkPlaces (_norm, height in alpha)"},
    {"nm", MapRole::Normal, "Cube 2 / Tesseract (_nm, height in alpha)"},
    {"n", MapRole::Normal, "Unreal naming (T_Name_N), game texture packs"},
    {"normalgl", MapRole::Normal, "ambientCG, lower case"},
    {"normaldx", MapRole::Normal, "ambientCG, lower case"},
    {"local", MapRole::Normal, "Doom 3 (_local)"},
    {"ddn", MapRole::Normal, "CryEngine (_ddn)"},
    {"ddna", MapRole::NormalGloss, "CryEngine (_ddna: gloss in alpha)"},
    {"bent normal", MapRole::Unused, "Substance", "bent normals"},
    {"world normal", MapRole::Unused, "Substance", "world-space normals"},
    {"object normal", MapRole::Unused, "baking tools", "object-space normals"},
    // Surface.
    {"roughness", MapRole::Roughness, "Node Wrangler, ambientCG, Quixel, Substance"},
    {"rough", MapRole::Roughness, "Node Wrangler, Poly Haven"},
    {"rgh", MapRole::Roughness, "Node Wrangler"},
    {"r", MapRole::Roughness, "Unreal naming (T_Name_R)"},
    {"gloss", MapRole::Gloss, "Node Wrangler, Quixel, Poliigon (_GLOSS)"},
    {"glossy", MapRole::Gloss, "Node Wrangler"},
    {"glossiness", MapRole::Gloss, "Node Wrangler"},
    {"smoothness", MapRole::Gloss, "Unity"},
    {"metallic", MapRole::Metallic, "Node Wrangler, Substance, Godot"},
    {"metalness", MapRole::Metallic, "Node Wrangler, ambientCG, Poliigon"},
    {"metal", MapRole::Metallic, "Node Wrangler, Poly Haven"},
    {"mtl", MapRole::Metallic, "Node Wrangler"},
    {"m", MapRole::Metallic, "Unreal naming (T_Name_M)"},
    {"ao", MapRole::Ao, "Node Wrangler, Poly Haven, Quixel, Poliigon"},
    {"ambient occlusion", MapRole::Ao, "Node Wrangler, ambientCG, Substance"},
    {"ambientocclusion", MapRole::Ao, "spelled together"},
    {"occlusion", MapRole::Ao, "Node Wrangler, Unity"},
    {"occ", MapRole::Ao, "abbreviation"},
    {"mixed ao", MapRole::Ao, "Substance (_Mixed_AO)"},
    {"arm", MapRole::Orm, "Poly Haven (AO, roughness, metallic)"},
    {"orm", MapRole::Orm, "Unreal, glTF, Godot (occlusion, roughness, metallic)"},
    {"occlusion roughness metallic", MapRole::Orm, "Substance's Unreal template"},
    {"occlusionroughnessmetallic", MapRole::Orm, "spelled together"},
    {"mask map", MapRole::MaskMap, "Unity HDRP (metallic, occlusion, detail, smoothness)"},
    {"maskmap", MapRole::MaskMap, "Unity HDRP"},
    {"metallic smoothness", MapRole::MetallicSmoothness, "Unity Standard"},
    {"metallicsmoothness", MapRole::MetallicSmoothness, "Unity Standard"},
    {"metallic gloss", MapRole::MetallicSmoothness, "Unity Standard (_MetallicGlossMap)"},
    {"specular", MapRole::Specular, "Node Wrangler, Quixel, Substance"},
    {"specularity", MapRole::Specular, "Node Wrangler"},
    {"spec", MapRole::Specular, "Node Wrangler, Poly Haven, CryEngine"},
    {"spc", MapRole::Specular, "Node Wrangler"},
    {"s", MapRole::Specular, "Doom 3 (_s), Cube 2 / Tesseract (_s)"},
    {"refl", MapRole::Specular, "Poliigon (_REFL)"},
    {"reflection", MapRole::Specular, "older texture packs"},
    // This project's own maps.
    {"cone", MapRole::Cone, "Parallax Studio"},
    {"relaxed cone", MapRole::RelaxedCone, "Parallax Studio"},
    {"relaxedcone", MapRole::RelaxedCone, "Parallax Studio"},
    {"rcone", MapRole::RelaxedCone, "Parallax Studio"},
    // Known, and not a parallax material's.
    {"emission", MapRole::Unused, "Node Wrangler, ambientCG", "emission"},
    {"emissive", MapRole::Unused, "Node Wrangler, Substance", "emission"},
    {"emit", MapRole::Unused, "Node Wrangler", "emission"},
    {"glow", MapRole::Unused, "DarkPlaces, Tesseract", "glow (emission)"},
    {"luma", MapRole::Unused, "DarkPlaces", "glow (emission)"},
    {"e", MapRole::Unused, "Unreal naming (T_Name_E)", "emission"},
    {"alpha", MapRole::Unused, "Node Wrangler", "opacity"},
    {"opacity", MapRole::Unused, "Node Wrangler, ambientCG, Quixel", "opacity"},
    {"alphamasked", MapRole::Unused, "Poliigon", "opacity"},
    {"transparency", MapRole::Unused, "Node Wrangler", "transmission"},
    {"transmission", MapRole::Unused, "Node Wrangler, Poliigon", "transmission"},
    {"translucency", MapRole::Unused, "Quixel", "translucency"},
    {"translucent", MapRole::Unused, "Poly Haven", "translucency"},
    {"sss", MapRole::Unused, "Node Wrangler, Poliigon", "subsurface scattering"},
    {"subsurface", MapRole::Unused, "Node Wrangler", "subsurface scattering"},
    {"cavity", MapRole::Unused, "Quixel", "cavity"},
    {"curvature", MapRole::Unused, "Substance", "curvature"},
    {"fuzz", MapRole::Unused, "Quixel", "fuzz (sheen)"},
    {"sheen", MapRole::Unused, "Substance", "sheen"},
    {"thickness", MapRole::Unused, "Substance", "thickness"},
    {"mask", MapRole::Unused, "Poly Haven, Poliigon", "mask"},
    {"id", MapRole::Unused, "Substance", "material ids"},
    {"pants", MapRole::Unused, "DarkPlaces", "team colour mask"},
    {"shirt", MapRole::Unused, "DarkPlaces", "team colour mask"},
    {"reflect", MapRole::Unused, "DarkPlaces", "reflection mask"},
    {"preview", MapRole::Unused, "texture libraries", "preview picture"},
    {"thumb", MapRole::Unused, "texture libraries", "preview picture"},
    {"thumbnail", MapRole::Unused, "texture libraries", "preview picture"},
};

std::string_view kRoleNames[] = {
    "albedo",
    "height map",
    "depth map",
    "bump map",
    "normal map",
    "normal map (gloss in alpha)",
    "roughness map",
    "gloss map",
    "metallic map",
    "occlusion map",
    "ORM map",
    "mask map",
    "metallic-smoothness map",
    "specular map",
    "cone map",
    "relaxed cone map",
    "map",
};

bool allDigits(std::string_view s) {
    return !s.empty() &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool digitsThen(std::string_view word, std::string_view tail) {
    return word.size() > tail.size() && word.ends_with(tail) &&
           allDigits(word.substr(0, word.size() - tail.size()));
}

bool wordThenDigits(std::string_view word, std::string_view head) {
    return word.size() > head.size() && word.starts_with(head) &&
           allDigits(word.substr(head.size()));
}

} // namespace

std::string_view roleName(MapRole role) {
    return kRoleNames[static_cast<int>(role)];
}

std::span<const MapTag> mapTags() {
    return kTags;
}

const MapTag* findMapTag(std::string_view words) {
    for (const MapTag& tag : kTags) {
        if (tag.words == words)
            return &tag;
    }
    return nullptr;
}

GreenHint greenHintOf(std::string_view word) {
    if (word == "gl" || word == "opengl" || word == "ogl")
        return GreenHint::OpenGL;
    if (word == "dx" || word == "directx")
        return GreenHint::DirectX;
    return GreenHint::None;
}

bool isNeutralWord(std::string_view word) {
    static constexpr std::array<std::string_view, 12> kFormats{
        "png", "jpg", "jpeg", "exr", "tif", "tiff", "tga", "bmp", "hdr", "webp", "psd", "dds"};
    if (std::find(kFormats.begin(), kFormats.end(), word) != kFormats.end())
        return word != "bmp"; // "bmp" is Node Wrangler's bump tag; as an extension it is gone
    if (digitsThen(word, "k") || digitsThen(word, "bit") || wordThenDigits(word, "lod") ||
        wordThenDigits(word, "var"))
        return true;
    if (const std::size_t x = word.find('x'); x != std::string_view::npos &&
                                              allDigits(word.substr(0, x)) &&
                                              allDigits(word.substr(x + 1)))
        return true; // 1024x1024
    if (allDigits(word) && word.size() >= 3 && word.size() <= 5) {
        const int n = std::stoi(std::string(word));
        return n >= 128 && n <= 16384 && (n & (n - 1)) == 0 && word[0] != '0';
    }
    return false;
}

} // namespace px

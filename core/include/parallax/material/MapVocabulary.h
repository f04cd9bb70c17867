#pragma once
// The words texture sets use for their maps, as one table (docs/texture-sets.md lists it with
// where each word comes from). A file name's last words say what the file holds: "_nor_gl",
// "NormalDX", "_ddna", "_arm", "Displacement", "z". The importer reads names only through here.

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace px {

// What a file holds as its name tells it. Packed roles hold several maps, one per channel.
enum class MapRole {
    Albedo,
    Height, // white = high
    Depth,  // white = deep (this project's "_depth")
    Bump,   // a grey bump map: a height map, unless its texels are a normal map
    Normal,
    NormalGloss, // CryEngine's _ddna: a normal map with gloss (not height) in alpha
    Roughness,
    Gloss, // smoothness: roughness = 1 - gloss
    Metallic,
    Ao,
    Orm,                // R occlusion, G roughness, B metallic (Unreal ORM, Poly Haven ARM)
    MaskMap,            // Unity HDRP: R metallic, G occlusion, B detail mask, A smoothness
    MetallicSmoothness, // Unity Standard: R metallic, A smoothness
    Specular,           // the material's specular map: kept for the engines that read one
    Cone,
    RelaxedCone,
    Unused, // known maps a parallax material does not use: emission, opacity, cavity, ...
};

std::string_view roleName(MapRole role); // "normal map (gloss in alpha)", for reports

struct MapTag {
    std::string_view words; // lower case, one space between words: "ambient occlusion"
    MapRole role;
    std::string_view origin;    // where the word is used: "Node Wrangler, Poly Haven"
    std::string_view what = {}; // for Unused: what the map is ("emission")
};

// The whole table, in the order docs/texture-sets.md lists it.
std::span<const MapTag> mapTags();

// The tag whose words are `words` (lower case, space-separated), if any.
const MapTag* findMapTag(std::string_view words);

// Words that may follow a normal map's tag to name its green convention ("gl", "dx", "opengl").
enum class GreenHint { None, OpenGL, DirectX };
GreenHint greenHintOf(std::string_view word);

// Words that say nothing about the map: resolution ("2k", "4096", "1024x1024"), file format or
// depth ("png", "exr", "16bit"), level of detail ("lod0").
bool isNeutralWord(std::string_view word);

} // namespace px

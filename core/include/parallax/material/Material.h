#pragma once
// A material: which maps, how to read them, and how to render them. Materials are data; the
// shader variant, the bakes and the exports are derived from them (docs/development.md,
// Architecture, "Variants as data"). The JSON form ("format": "parallax-studio-material",
// "version": 1) lives in MaterialFile.h.

#include "parallax/bake/NormalGreen.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/trace/Technique.h"

#include <optional>
#include <string>

namespace px {

// Where the shading normal comes from.
enum class NormalSource {
    None,          // the polygon's normal
    Map,           // the material's normal map
    HeightCentral, // derived from height in the shader: 4-tap central differences
    HeightSobel,   // derived from height in the shader: 3x3 Sobel
};

enum class LightingModel { BlinnPhong, MetallicRoughness };

struct MaterialMaps {
    // Paths as written in the file: relative to the material file's folder, or absolute.
    // Empty means absent.
    std::string albedo;      // sRGB
    std::string height;      // linear; a depth map if heightIsDepth
    std::string normal;      // linear, tangent space, green as normalGreen says
    std::string cone;        // R = height, G = sqrt(conservative cone ratio)
    std::string relaxedCone; // R = height, G = sqrt(relaxed cone ratio)
    std::string ao;
    std::string roughness;
    std::string metallic;
    // Specular level, as stored: scales the specular reflection of non-metals (white = the full,
    // default reflection, black = none); a coloured file tints it. Kept for the engines that
    // read one (docs/export.md); the preview does not.
    std::string specular;
};

// Technique "auto": no technique of its own; resolved where the material is rendered or exported
// to the cheapest setting whose hit error stays within `budget` texels (p99) at every view angle up
// to `maxPolar` degrees (parallax/eval/AutoTechnique.h). Until then `technique` and `params` hold
// a placeholder (pom's defaults) or the last resolution.
struct AutoQuality {
    float budget = 0.5f;
    float maxPolar = 80.0f;
    // A budget in screen pixels instead: `budgetPixels` x `texelsPerPixel` texels (the texel
    // density where the material is seen most closely), both set or neither.
    std::optional<float> budgetPixels;
    std::optional<float> texelsPerPixel;
    float budgetTexels() const {
        return budgetPixels && texelsPerPixel ? *budgetPixels * *texelsPerPixel : budget;
    }
};

// Which channel of their files the occlusion, roughness and metallic maps read: a packed file
// (Unreal's ORM, Unity's mask map, CryEngine's gloss in a normal map's alpha) serves several maps.
struct SurfaceChannels {
    HeightChannel ao = HeightChannel::Red;
    HeightChannel roughness = HeightChannel::Red;
    HeightChannel metallic = HeightChannel::Red;
    bool gloss = false; // the roughness file holds gloss (smoothness): roughness = 1 - value
    bool operator==(const SurfaceChannels&) const = default;
};

// Where the light the material was last seen under comes from (docs/conventions.md's angles as
// the editor's light: azimuth about the up axis, elevation above the surface's plane), degrees.
struct LightDirection {
    float azimuthDeg = 135.0f;
    float elevationDeg = 40.0f;
    bool operator==(const LightDirection&) const = default;
};

struct Material {
    std::string name = "untitled";
    MaterialMaps maps;
    SurfaceChannels surface;
    HeightChannel heightChannel = HeightChannel::Red;
    bool heightIsDepth = false; // white = deep: loaded inverted
    // The file values for h = 0 and h = 1 (a float height map in its own units); unset: values as
    // stored, within [0, 1]. The height scale is the depth of the whole range either way.
    std::optional<HeightRange> heightRange;
    // Set when the height map was made by integrating this normal map (its file name): a guess at
    // the relief, not a measured one; exports say so.
    std::string heightDerivedFrom;
    float heightScale = 0.05f; // s, uv units (docs/conventions.md §2)
    WrapMode wrap = WrapMode::Repeat;
    float tiling = 1.0f; // uv repeats across a mesh

    Technique technique = Technique::Pom;
    TraceParams params = info(Technique::Pom).defaults;
    std::optional<AutoQuality> autoQuality; // set: the technique is "auto"

    NormalSource normalSource = NormalSource::HeightCentral;
    NormalGreen normalGreen = NormalGreen::OpenGL;

    bool selfShadow = false;
    float shadowSoftness = 0.5f; // 0 hard .. 1 very soft

    LightingModel lighting = LightingModel::BlinnPhong;
    float roughness = 0.6f; // used where there is no roughness map
    float metallic = 0.0f;  // used where there is no metallic map
    float specular = 0.3f;  // Blinn-Phong specular strength
    float shininess = 32.0f;
    // The light the material was saved under in the editor; unset: the viewer's own.
    std::optional<LightDirection> light;
};

} // namespace px

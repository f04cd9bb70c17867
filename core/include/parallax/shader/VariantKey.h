#pragma once
// Which shader a scene needs (STYLE.md, "variants as data"): a handful of feature bits decided by
// the material and the view options. isValid() rejects impossible combinations; canonical()
// collapses keys that would generate the same shader (a feature the technique never reads), so
// a cache keyed by canonical keys compiles each distinct shader once.

#include "parallax/Result.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/material/Material.h"
#include "parallax/trace/Technique.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace px {

// Where the tangent frame comes from: the mesh's per-vertex T and B, or screen-space derivatives
// of position and uv (meshes without tangents).
enum class TbnSource { VertexTangents, Derivatives };

// What the fragment shader writes.
enum class ShaderOutput {
    Color,   // the shaded, sRGB-encoded colour
    Surface, // (u, v, t, fetches) of each pixel's hit, into a float target: heat maps and tests
    Trace,   // the canonical trace scene (docs/conventions.md §5): pixel (i, j) is ray (i, j)
};

struct VariantKey {
    Technique technique = Technique::Pom;
    bool shadow = false;
    NormalSource normalSource = NormalSource::HeightCentral;
    bool albedoMap = false;
    bool surfaceMap = false; // packed occlusion / roughness / metallic (any of the three maps)
    WrapMode wrap = WrapMode::Repeat;
    LightingModel lighting = LightingModel::BlinnPhong;
    TbnSource tbn = TbnSource::VertexTangents;
    ShaderOutput output = ShaderOutput::Color;

    // The key as 14 bits (technique 0-3, shadow 4, normal source 5-6, albedo 7, surface 8,
    // wrap 9, lighting 10, tbn 11, output 12-13): a cache index and a stable name.
    std::uint32_t bits() const;
    static std::optional<VariantKey> fromBits(std::uint32_t bits);

    // False for impossible keys: `normal` without a normal source, out-of-range enums.
    bool isValid() const;
    // The reason isValid() is false, as a sentence.
    Status validate() const;

    // Which maps and uniforms the variant reads (after canonical()).
    bool readsHeightMap() const;

    // "pom+shadow+central+albedo+clamp" style, for file names, logs and `shader --list`.
    std::string name() const;

    friend bool operator==(const VariantKey&, const VariantKey&) = default;
};

inline constexpr int kVariantKeyBits = 14;
inline constexpr std::uint32_t kVariantKeyCount = 1u << kVariantKeyBits;

// Clears every bit the key's technique and output never read: shadow only on parallax techniques,
// no normals and no material maps in the trace or surface outputs, wrap only where the height map
// is read, roughness/metallic only with the metallic-roughness model (Blinn-Phong reads only the
// occlusion channel of the surface map). A parallax technique whose hit nothing reads (no map, no
// shadow, no clamp discard) draws exactly as `none` and becomes `none`. Idempotent.
VariantKey canonical(VariantKey key);

// Every valid canonical key, in bits() order: what `parallax-cli shader --dump-all` writes and
// what the tests compile.
std::vector<VariantKey> allVariants();

// The key a material asks for with the maps it actually has (paths non-empty).
VariantKey variantFor(const Material& material, ShaderOutput output = ShaderOutput::Color);

} // namespace px

#pragma once
// Which shader a scene needs (docs/development.md, Architecture, "Variants as data"): a handful of
// feature bits decided by the material and the view options. isValid() rejects impossible
// combinations; canonical() collapses keys that would generate the same shader (a feature the
// technique never reads), so a cache keyed by canonical keys compiles each distinct shader once.

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
    // As Surface, but `exact` walks the height level the pixel's footprint asks for (the level
    // the marching techniques read), not level 0: the reference on the filtered surface they
    // march (the editor's technique and filtering errors). Verify kernels only (a gather reads
    // level 0); other techniques draw as Surface.
    FootprintSurface,
};

// How the kernels read the height and cone maps. Production: as an engine would, through the
// texture units (hardware bilinear filtering and mip selection, textureGather for a cell's
// corners), no fetch counter where nothing reads it, no `precise`. Verify: texelFetch and the
// filtering written out in the shared code, so the GPU matches the CPU to the bit (the tests that
// hold GPU == CPU).
enum class KernelFlavour { Production, Verify };

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
    KernelFlavour flavour = KernelFlavour::Production;
    // Image-based light from an environment (and exposure, tone map) instead of the constant
    // ambient fill; the directional light stays as the sun.
    bool environment = false;

    // The key as 16 bits (technique 0-3, shadow 4, normal source 5-6, albedo 7, surface 8,
    // wrap 9, lighting 10, tbn 11, output 12-13, flavour 14, environment 15): a cache index and a
    // stable name.
    std::uint32_t bits() const;
    static std::optional<VariantKey> fromBits(std::uint32_t bits);

    // False for impossible keys: `normal` without a normal source, out-of-range enums.
    bool isValid() const;
    // The reason isValid() is false, as a sentence.
    Status validate() const;

    // Which maps and uniforms the variant reads (after canonical()).
    bool readsHeightMap() const;

    // "pom+shadow+central+albedo+clamp" style, for file names, logs and `shader --list`; the
    // verify flavour ends in "+verify".
    std::string name() const;

    friend bool operator==(const VariantKey&, const VariantKey&) = default;
};

inline constexpr int kVariantKeyBits = 16;
inline constexpr std::uint32_t kVariantKeyCount = 1u << kVariantKeyBits;

// Clears every bit the key's technique and output never read: shadow only on parallax techniques,
// no normals and no material maps in the trace or surface outputs, wrap only where the height map
// is read, roughness/metallic only with the metallic-roughness model (Blinn-Phong reads only the
// occlusion channel of the surface map). A parallax technique whose hit nothing reads (no map, no
// shadow, no clamp discard) draws exactly as `none` and becomes `none`. A variant that reads no
// height map has one flavour, production. The environment lights the colour output only, in the
// production flavour (the verify kernels serve the hit data, which no light changes). The footprint
// surface output is `exact`'s alone, in the verify flavour; any other technique's is Surface.
// Idempotent.
VariantKey canonical(VariantKey key);

// Every valid canonical key, in bits() order: what `parallax-cli shader --dump-all` writes and
// what the tests compile.
std::vector<VariantKey> allVariants();

// The key a material asks for with the maps it actually has (paths non-empty).
VariantKey variantFor(const Material& material, ShaderOutput output = ShaderOutput::Color);

// The kernel flavours' names: "production", "verify" (`--kernels`, variant names).
namespace shader {
std::optional<KernelFlavour> parseKernelFlavour(std::string_view name);
std::string_view kernelFlavourName(KernelFlavour flavour);
} // namespace shader

} // namespace px

#include "parallax/shader/VariantKey.h"

#include "parallax/material/MaterialNames.h"

#include <array>

namespace px {

namespace {

constexpr int kTechniqueCount = static_cast<int>(Technique::Exact) + 1;
static_assert(kTechniqueCount <= 16, "the technique takes 4 bits of a variant key");

constexpr std::array<std::string_view, 2> kFlavourNames{"production", "verify"};

} // namespace

std::uint32_t VariantKey::bits() const {
    std::uint32_t b = static_cast<std::uint32_t>(technique);
    b |= (shadow ? 1u : 0u) << 4;
    b |= static_cast<std::uint32_t>(normalSource) << 5;
    b |= (albedoMap ? 1u : 0u) << 7;
    b |= (surfaceMap ? 1u : 0u) << 8;
    b |= (wrap == WrapMode::Clamp ? 1u : 0u) << 9;
    b |= (lighting == LightingModel::MetallicRoughness ? 1u : 0u) << 10;
    b |= (tbn == TbnSource::Derivatives ? 1u : 0u) << 11;
    b |= static_cast<std::uint32_t>(output) << 12;
    b |= (flavour == KernelFlavour::Verify ? 1u : 0u) << 14;
    b |= (environment ? 1u : 0u) << 15;
    return b;
}

std::optional<VariantKey> VariantKey::fromBits(std::uint32_t b) {
    if (b >= kVariantKeyCount)
        return std::nullopt;
    const std::uint32_t technique = b & 15u;
    const std::uint32_t output = (b >> 12) & 3u;
    if (technique >= kTechniqueCount || output > 3)
        return std::nullopt;
    VariantKey k;
    k.technique = static_cast<Technique>(technique);
    k.shadow = (b >> 4) & 1u;
    k.normalSource = static_cast<NormalSource>((b >> 5) & 3u);
    k.albedoMap = (b >> 7) & 1u;
    k.surfaceMap = (b >> 8) & 1u;
    k.wrap = (b >> 9) & 1u ? WrapMode::Clamp : WrapMode::Repeat;
    k.lighting = (b >> 10) & 1u ? LightingModel::MetallicRoughness : LightingModel::BlinnPhong;
    k.tbn = (b >> 11) & 1u ? TbnSource::Derivatives : TbnSource::VertexTangents;
    k.output = static_cast<ShaderOutput>(output);
    k.flavour = (b >> 14) & 1u ? KernelFlavour::Verify : KernelFlavour::Production;
    k.environment = (b >> 15) & 1u;
    return k;
}

Status VariantKey::validate() const {
    if (static_cast<int>(technique) < 0 || static_cast<int>(technique) >= kTechniqueCount)
        return Error{"the variant's technique is out of range"};
    if (static_cast<int>(normalSource) < 0 || static_cast<int>(normalSource) > 3)
        return Error{"the variant's normal source is out of range"};
    if (static_cast<int>(output) < 0 || static_cast<int>(output) > 3)
        return Error{"the variant's output is out of range"};
    if (technique == Technique::Normal && normalSource == NormalSource::None &&
        output == ShaderOutput::Color)
        return Error{"the normal technique needs a normal source (a normal map or the height map)"};
    return success();
}

bool VariantKey::isValid() const {
    return validate().ok();
}

bool VariantKey::readsHeightMap() const {
    return info(technique).parallax || shadow || normalSource == NormalSource::HeightCentral ||
           normalSource == NormalSource::HeightSobel;
}

std::string VariantKey::name() const {
    std::string n(info(technique).name);
    if (shadow)
        n += "+shadow";
    if (normalSource == NormalSource::Map)
        n += "+normal-map";
    else if (normalSource != NormalSource::None)
        n += "+" + std::string(shortName(normalSource));
    if (albedoMap)
        n += "+albedo";
    if (surfaceMap)
        n += "+orm";
    if (wrap == WrapMode::Clamp)
        n += "+clamp";
    if (lighting == LightingModel::MetallicRoughness)
        n += "+metallic-roughness";
    if (tbn == TbnSource::Derivatives)
        n += "+derivative-tbn";
    if (output == ShaderOutput::Surface)
        n += "+surface";
    else if (output == ShaderOutput::Trace)
        n += "+trace";
    else if (output == ShaderOutput::FootprintSurface)
        n += "+footprint-surface";
    if (environment)
        n += "+environment";
    if (flavour == KernelFlavour::Verify)
        n += "+verify";
    return n;
}

VariantKey canonical(VariantKey k) {
    if (k.output == ShaderOutput::FootprintSurface) {
        if (k.technique == Technique::Exact)
            k.flavour = KernelFlavour::Verify; // textureGather reads level 0 only
        else
            k.output = ShaderOutput::Surface; // only `exact` reads another level here
    }
    if (k.output != ShaderOutput::Color) {
        // The hit data only: nothing is shaded.
        k.shadow = false;
        k.normalSource = NormalSource::None;
        k.albedoMap = false;
        k.surfaceMap = false;
        k.lighting = LightingModel::BlinnPhong;
        k.environment = false;
        if (k.output == ShaderOutput::Trace)
            k.tbn = TbnSource::VertexTangents; // no mesh
    }
    if (!info(k.technique).parallax)
        k.shadow = false; // shadows are traced from a hit: only parallax techniques have one
    if (k.technique == Technique::None)
        k.normalSource = NormalSource::None; // plain texture
    if (k.output == ShaderOutput::Color && info(k.technique).parallax &&
        k.normalSource == NormalSource::None && !k.albedoMap && !k.surfaceMap && !k.shadow &&
        k.wrap == WrapMode::Repeat)
        k.technique =
            Technique::None; // nothing reads the hit (no map, no discard): it draws as none
    if (!k.readsHeightMap()) {
        k.wrap = WrapMode::Repeat; // the other maps' wrap is sampler state, not shader code
        k.flavour = KernelFlavour::Production; // the flavours differ only in height and cone reads
    }
    if (k.environment)
        k.flavour = KernelFlavour::Production;
    return k;
}

std::vector<VariantKey> allVariants() {
    std::vector<VariantKey> keys;
    for (std::uint32_t b = 0; b < kVariantKeyCount; ++b) {
        const std::optional<VariantKey> k = VariantKey::fromBits(b);
        if (k && k->isValid() && canonical(*k) == *k)
            keys.push_back(*k);
    }
    return keys;
}

VariantKey variantFor(const Material& m, ShaderOutput output) {
    VariantKey k;
    k.technique = m.technique;
    k.shadow = m.selfShadow;
    k.normalSource = m.normalSource;
    // A material that asks for its normal map but names none derives normals from height.
    if (k.normalSource == NormalSource::Map && m.maps.normal.empty())
        k.normalSource = NormalSource::HeightCentral;
    k.albedoMap = !m.maps.albedo.empty();
    k.surfaceMap = !m.maps.ao.empty() || !m.maps.roughness.empty() || !m.maps.metallic.empty();
    k.wrap = m.wrap;
    k.lighting = m.lighting;
    k.output = output;
    return canonical(k);
}

namespace shader {

std::optional<KernelFlavour> parseKernelFlavour(std::string_view name) {
    for (std::size_t i = 0; i < kFlavourNames.size(); ++i) {
        if (kFlavourNames[i] == name)
            return static_cast<KernelFlavour>(i);
    }
    return std::nullopt;
}

std::string_view kernelFlavourName(KernelFlavour flavour) {
    return kFlavourNames.at(static_cast<std::size_t>(flavour));
}

} // namespace shader

} // namespace px

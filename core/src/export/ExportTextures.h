#pragma once
// Turning a material's maps into the textures a target expects: bit depth, channel packing, cone
// maps quantised downwards (normal maps: convertNormalMap, parallax/bake/NormalMapBaker.h).

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"
#include "parallax/material/Material.h"

#include <optional>

namespace px::exporter {

// One channel: h (white = high), or 1 - h for a target told to read a depth map.
Image heightImage(const HeightField& field, bool asDepth);

// R = height, G = sqrt(cone ratio) rounded *down* to the steps of `bits` (8 or 16; 32: float,
// kept) so a stored cone is never wider than the baked one (docs/conventions.md §4).
Image coneImage(const HeightField& field, const ConeMap& cone, int bits);

// A specular map as one level a texel: a grey file's value, a coloured one's strongest channel
// (as KHR_materials_specular turns a colour into a strength).
Image specularLevel(const Image& specular);

// Bilinear resampling between texel centres, with the material's wrap mode at the edges.
Image resample(const Image& image, int width, int height, WrapMode wrap);

// Where one channel of a packed texture comes from: a channel of a map, or a constant.
struct ChannelSource {
    const Image* image = nullptr; // empty or null: use `constant`
    int channel = 0;
    bool invert = false; // 1 - value (smoothness from roughness)
    float constant = 0.0f;
};

// A `channels`-channel texture (up to 4), each channel from its source, every map resampled to
// the largest size among them. nullopt when no source has an image (nothing to pack).
std::optional<Image> packChannels(const ChannelSource* sources, int channels, WrapMode wrap);

} // namespace px::exporter

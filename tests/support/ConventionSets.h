#pragma once
// Texture sets named and packed as texture libraries and engines do, written by the tests with
// known truth: which file holds what, the height (white = high), the normal map's green.

#include "parallax/heightfield/HeightField.h"
#include "parallax/image/Image.h"
#include "parallax/material/Material.h"

#include <string>
#include <vector>

namespace px::test {

// What a file's texels are.
enum class Texels {
    Albedo,            // colourful noise: neither grey nor a normal map
    Height,            // the truth, white = high
    Depth,             // 1 - the truth
    Normal,            // baked from the truth
    NormalHeightAlpha, // the normal map with the height in alpha (Cube 2 _nm, DarkPlaces _norm)
    NormalDepthAlpha,  // ... with 1 - height in alpha
    NormalGlossAlpha,  // the normal map with an unrelated gloss in alpha (CryEngine _ddna)
    Grey,              // an unrelated grey map (roughness, gloss, specular, occlusion)
    Packed,            // R = 0.2, G = 0.5, B = 0.8, A = 0.3 plus a little texture
};

struct ConventionFile {
    std::string name; // "rock_nor_gl_1k.png"; the extension chooses the format
    Texels texels;
};

struct ConventionTruth {
    HeightField height; // white = high
    NormalGreen green = NormalGreen::OpenGL;
};

// Writes each file into `folder`: heights as 16-bit where the format allows (8-bit JPEG), the
// normal map baked at height scale 0.05 with `green`. The height map comes from `seed`.
ConventionTruth writeConventionSet(const std::string& folder,
                                   const std::vector<ConventionFile>& files, unsigned seed,
                                   NormalGreen green, int size = 64);

// `rgb`'s first three channels with `alpha` as the fourth (a normal map packed as games pack it).
Image withAlpha(const Image& rgb, const HeightField& alpha);

// The packed file's channel values at texel (x, y): R, G, B, A.
float packedValue(int channel, int x, int y);

} // namespace px::test

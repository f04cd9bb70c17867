#pragma once
// Texture sets the import tests write themselves: a height file (as a height or a depth map), the
// normal map baked from it (OpenGL or DirectX green) and an albedo named with or without a suffix.

#include "parallax/heightfield/HeightField.h"
#include "parallax/material/Material.h"

#include <string>

namespace px::test {

struct TextureSetSpec {
    std::string stem = "rock";
    bool depth = false;                      // the height file stores 1 - h
    NormalGreen green = NormalGreen::OpenGL; // the normal map's convention
    bool albedoSuffix = true;                // "rock_albedo.png", else "rock.png"
    bool normal = true;                      // write a normal map
    std::string heightSuffix;                // default: "_depth"/"_height" would give it away
    int size = 64;
    unsigned seed = 1;
    // Non-zero: the height file is a float EXR in its maker's units, offset + scale * value.
    float fileScale = 0.0f;
    float fileOffset = 0.0f;
};

struct WrittenSet {
    HeightField height; // what the material must end up with: white = high (before any range)
    HeightField file;   // the height file's values
    std::string heightFile, normalFile, albedoFile;
};

// Writes the set into `folder` (16-bit height or float EXR, 8-bit normal and albedo PNGs). The
// height map is
// a procedural one chosen by the seed (noise, stones or bricks); the suffix is "_disp" unless told.
WrittenSet writeTextureSet(const std::string& folder, const TextureSetSpec& spec);

} // namespace px::test

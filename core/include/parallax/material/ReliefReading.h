#pragma once
// How to read a texture set's relief: is its height file a height map or a depth map, and which
// way does its normal map's green point? `_disp` files are depth maps in some sets and height maps
// in others, and tools disagree on green (docs/conventions.md §2, §3), so a file name cannot say. When a
// normal map is there, the data can: under the right reading the normal map's slopes follow the
// height map's (red with -dh/du, green with +dh/dv in OpenGL convention). The four readings
// (height or depth × OpenGL or DirectX green) are scored and the most consistent is kept.

#include "parallax/Result.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"
#include "parallax/material/Material.h"

#include <string>

namespace px {

struct ReliefReading {
    bool depth = false;                      // the file is a depth map: white = deep
    NormalGreen green = NormalGreen::OpenGL; // the normal map's convention
    bool fromData = false;                   // told by the normal map (else by the file names)
    // Pearson correlations of the normal map's red with -dh/du and green with +dh/dv, read as a
    // height map with OpenGL green; the chosen reading's score is (±slopeU ± slopeV) / 2.
    double slopeU = 0.0;
    double slopeV = 0.0;
    double score = 0.0;  // the chosen reading's agreement, -1..1 (1: the slopes agree everywhere)
    std::string summary; // one sentence saying what was decided and how sure
};

// Scores the four readings of `file` (the height file's values as stored, not inverted) against
// `normals` (n * 0.5 + 0.5; sizes may differ). Falls back to the names' guess `depthByName`, with
// fromData false, when the maps do not correlate (|r| < 0.2 on both axes: not each other's maps,
// or flat). Errors: a normal map with fewer than two channels, an empty map.
Result<ReliefReading> readRelief(const HeightField& file, const Image& normals, WrapMode wrap,
                                 bool depthByName, const std::string& normalSource);

// The reading of a set without a normal map: the names' guess, said prominently.
ReliefReading reliefByName(bool depthByName, const std::string& heightFile);

} // namespace px

#pragma once
// A height map made from a normal map, for texture sets that ship only a normal map: the surface
// whose slopes are closest, in least squares, to the normal map's (the Poisson problem of
// Frankot & Chellappa 1988 and Simchony, Chellappa & Shao 1990). Solved exactly in the Fourier
// basis that diagonalises the problem: the DFT where the map tiles (periodic borders), the DCT
// where it does not (no slope assumed across the border). A guess at the relief, not a
// measurement: the normal map's lost steps and its smoothing stay lost.

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/NormalGreen.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/image/Image.h"

#include <optional>

namespace px {

struct HeightFromNormalsOptions {
    NormalGreen green = NormalGreen::OpenGL;
    // Whether the map tiles: unset tells it from the texels (the seams across the borders
    // against the steps inside).
    std::optional<bool> periodic;
    // The normal map's mean slope is removed unless this is set: an 8-bit bias of its red or
    // green (a mean of 115 for 128) is such a slope, and integrated it would be a ramp across the
    // tile, a cliff at every border when tiled, and the largest part of the height scale. Kept,
    // it is integrated with free borders only (a periodic height cannot climb).
    bool keepTilt = false;
};

struct DerivedHeight {
    HeightField height;       // white = high, spanning [0, 1]
    float heightScale = 0.0f; // the relief's depth in uv units: the material's height scale
    bool periodic = false;    // which borders were used
    // The mean slope removed (HeightFromNormalsOptions::keepTilt): how much a plane with the
    // normal map's mean slope climbs across the tile along u and v, in uv units (the height
    // scale's). Zero when it was kept.
    double tiltU = 0.0, tiltV = 0.0;
    // How far the normal map is from being one surface's: RMS of the slopes not explained by the
    // height, over the RMS of the slopes (0: exactly a gradient field).
    double misfit = 0.0;
};

// n * 0.5 + 0.5 in R, G, B. Errors: fewer than three channels, a map smaller than 2 x 2, a flat
// map (no relief to make), cancellation.
Result<DerivedHeight> heightFromNormals(const Image& normals,
                                        const HeightFromNormalsOptions& options = {},
                                        const BakeControl& control = {});

} // namespace px

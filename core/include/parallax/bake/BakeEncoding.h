#pragma once
// Baked maps as images to write or upload, rounded the safe way for the pixel format:
// cone ratios (G) round down, so a stored cone is never wider; heights and maxima round up, so a
// stored apex is never lower and a stored maximum still bounds its cells (docs/cone-maps.md §1).
// Float formats keep values as they are.

#include "parallax/bake/ConeMap.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/image/Image.h"
#include "parallax/image/ImageFile.h"

namespace px {

// 255 or 65535 for 8- and 16-bit formats, 0 for half and float (no rounding).
int quantisationSteps(PixelFormat format);

// The smallest step of `steps` at or above v (v in [0, 1]); v itself when steps is 0.
float roundUpToStep(float v, int steps);

// The height field as an integer file stores it, rounded up. Bake cone maps from this field to
// make a cone map file self-consistent: its cones then hold for the surface its R channel gives.
HeightField roundHeightsUp(const HeightField& field, PixelFormat format);

// R = height (rounded up), G = sqrt(cone ratio) (rounded down), B = 0. `cones` by value: moved
// in, it is rounded in place (an 8192² map: 256 MiB less at the bake's peak).
Image encodeConeMap(const HeightField& heights, ConeMap cones, PixelFormat format);

enum class PyramidLayout {
    Atlas, // MaxMipPyramid::atlas(): every level stacked, what the GPU reads with texelFetch
    Chain, // level 0 on the left, the others stacked in a column to its right: for looking at
};

// A one-channel image of the pyramid (maxima rounded up), or of one level if level >= 0.
Image encodePyramid(const MaxMipPyramid& pyramid, PyramidLayout layout, int level,
                    PixelFormat format);

} // namespace px

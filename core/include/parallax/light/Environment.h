#pragma once
// Environments for image-based light: equirectangular radiance maps, linear RGB. Direction d maps
// to u = atan2(d.x, d.z) / 2pi + 1/2 (u = 1/2 looks along +z, the front), v = acos(d.y) / pi (row 0
// is the zenith, the file's top row); +y is up, as the preview's light and camera angles.

#include "parallax/Result.h"
#include "parallax/image/Image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

namespace px {

glm::vec2 equirectUv(glm::vec3 direction);
glm::vec3 equirectDirection(glm::vec2 uv);
// Bilinear, u wrapping, v clamped; a grey map gives grey.
glm::vec3 sampleEquirect(const Image& map, glm::vec3 direction);

// Reads an equirectangular HDR or EXR (any image the project reads) as RGB radiance, or one face
// of a sky box of six named as CubeMapSky.h says (the six made equirectangular). Errors name the
// file: missing, not an image, NaN/Inf or negative texels, not twice as wide as high (and not a
// cube face), a cube's face missing or of another size.
// Larger than 2048 x 1024 is resampled down to that (the prefilter needs no more). Grey maps, with
// or without alpha, give grey light; alpha is ignored.
Result<Image> loadEnvironment(const std::string& path);

// The map resampled to `width` x width/2 whatever the ratio (an area-weighted tent filter: the
// light of every texel is kept, none turns negative).
Image resampledEnvironment(const Image& map, int width);

// The built-in environment, made here (no image file): a blue sky brightening to a hazy
// horizon, a sun at `sunDirection` (the preview's directional light, so the sun that shadows is
// the one in the sky) and a warm grey ground. Radiance in linear units where the horizon is
// about 1. `width` x width/2 texels.
Image makeSkyEnvironment(glm::vec3 sunDirection, int width = 512);

// The same map with every texel times `factor` (a brighter or dimmer environment).
Image scaledEnvironment(Image map, float factor);

} // namespace px

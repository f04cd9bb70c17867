#pragma once
// Turning the core's maps into GL textures. Rows go up in file order (row 0 = v 0, the top of the
// image) and texelFetch(x, y) reads texel (x, y) as the core counts it: no flip
// (docs/conventions.md §1).

#include "parallax/Result.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"
#include "parallax/render/GlObjects.h"

#include <vector>

namespace px::gl {

enum class HeightFormat { R16, R32F };

// True if every texel is k / 65535 for an integer k (8- and 16-bit files): R16 holds it exactly.
bool fitsR16(const HeightField& field);

// Height map: R16 when it fits (8/16-bit files), else R32F; never 8 bits. Mipmapped (the
// marching techniques read the level the pixel's footprint asks for). Fails over the GL's
// maximum texture size.
Result<Object> uploadHeight(const HeightField& field, HeightFormat format);

// sRGB-encoded albedo (1-4 channels) decoded to linear RGBA16F, mipmapped.
Result<Object> uploadAlbedo(const Image& albedo);
// Tangent-space normal map, RGBA16, mipmapped.
Result<Object> uploadNormalMap(const Image& normal);
// Occlusion, roughness and metallic packed into one RGBA16 (glTF's ORM order); absent maps are
// 1 and the others are resampled to the largest one's size.
Result<Object> uploadOrm(const Image* ao, const Image* roughness, const Image* metallic);
enum class ConeFormat { RG16, RG32F };

// True if every cone is exactly k / 65535 (16-bit files, bakes rounded down to 16 bits): with
// heights that fit R16, RG16 holds the cone map exactly in half the memory of RG32F.
bool fitsRG16(const ConeMap& cones);

// R the height, G sqrt(cone ratio), level 0 only, bilinear.
Result<Object> uploadConeMap(const HeightField& field, const ConeMap& cones, ConeFormat format);
// R32F max-mip atlas (MaxMipPyramid::atlas()); `rows` receives each level's first row.
Result<Object> uploadMaxMipAtlas(const MaxMipPyramid& pyramid, std::vector<int>& rows);
// RG32F from two floats per texel, level 0 only, bilinear.
Result<Object> uploadRg32f(int width, int height, const std::vector<float>& texels);

// The wrap mode alone: the height and cone maps, which the production kernels filter in hardware
// with the material's wrap (CONVENTIONS §1: every sampler uses it).
void setWrap(const Object& texture, WrapMode wrap);

// Sampler state for filtered maps: wrap as the material says, trilinear, 8x anisotropic where the
// GL offers it and is not a software renderer.
void setFilteredSampling(const Object& texture, WrapMode wrap);

} // namespace px::gl

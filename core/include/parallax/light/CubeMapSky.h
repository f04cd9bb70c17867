#pragma once
// Sky boxes as six cube faces, as games ship them, turned into the equirectangular map the
// lighting reads (Environment.h). The faces are read as an OpenGL samplerCube reads them
// (GL_TEXTURE_CUBE_MAP_POSITIVE_X ... NEGATIVE_Z, row 0 of each file at the top), in the
// environment's frame (+y up, +z the front), so the sky looks as it does in a GL skybox.
//
// Face names, the last word of the file's name after _ - . or space (any case), one family a set:
//   +X px posx right rt     -X nx negx left lf
//   +Y py posy top up       -Y ny negy bottom dn
//   +Z pz posz front ft     -Z nz negz back bk
// ("sky_px.hdr", "posx.jpg", "Right.png", "mountain_ft.tga").

#include "parallax/Result.h"
#include "parallax/image/Image.h"

#include <array>
#include <optional>
#include <string>

namespace px {

enum class CubeFace { PositiveX, NegativeX, PositiveY, NegativeY, PositiveZ, NegativeZ };

// Which face `path` names and the six files of its set (the same folder, prefix, family, case and
// extension), in CubeFace order; nothing where the name names no face.
struct CubeFaceFiles {
    CubeFace face = CubeFace::PositiveX;
    std::array<std::string, 6> paths;
};
std::optional<CubeFaceFiles> cubeFaceFiles(const std::string& path);

// The cube's faces (square, one size, RGB) sampled bilinearly, each within itself, at every
// texel's direction of a `width` x width/2 equirectangular map.
Image equirectFromCube(const std::array<Image, 6>& faces, int width);

// Reads the six faces `files` names: every one must exist, be square and of one size, with no
// negative or non-finite radiance (errors name the file). The map is 4 faces wide (the face's
// texels at the horizon), at most `maxWidth`.
Result<Image> loadCubeMapSky(const CubeFaceFiles& files, int maxWidth);

} // namespace px

#pragma once
// PLY and STL checked before Assimp reads them, as the preview's loader checks OBJ and glTF
// (mesh/MeshFileChecks.h): the counts the file declares against the triangle limit and against
// the bytes it holds, so that what Assimp allocates is bounded by the file. Errors name the file.

#include "parallax/Result.h"
#include "parallax/io/Inputs.h"

#include <cstddef>

namespace px::meshbake {

Status checkPly(const InputFile& file, std::size_t maxTriangles);
Status checkStl(const InputFile& file, std::size_t maxTriangles);

// "N triangles, more than the bake's limit of M".
Error tooManyTriangles(const std::string& file, std::size_t triangles, std::size_t limit);

} // namespace px::meshbake

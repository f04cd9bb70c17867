#pragma once
// The checks a mesh file passes before Assimp reads it, so that what Assimp allocates is bounded
// by the file's real size and the triangle limit, and every file it references lies under the
// mesh's root (MeshScope): a GLB's chunk lengths against the file, a glTF's buffers, views and
// accessors against their buffers, its index values against its vertices, an OBJ's faces counted
// by streaming. Errors name the mesh file.

#include "MeshScope.h"
#include "parallax/Result.h"

#include <cstddef>

namespace px::mesh {

Status checkGltf(const InputFile& file, const MeshScope& scope, std::size_t maxTriangles);
Status checkObj(const InputFile& file, const MeshScope& scope, std::size_t maxTriangles);

// "N triangles, more than the preview's limit of M" (the loader says it the same way).
Error tooManyTriangles(const std::string& file, std::size_t triangles, std::size_t limit);

} // namespace px::mesh

#pragma once
// The artist's own mesh for the preview: OBJ and glTF 2.0 (.gltf, .glb) read by Assimp, checked,
// centred and scaled into the unit sphere (uniformly: the relief keeps its size relative to the
// mesh), uv in glTF's convention (docs/conventions.md §1) and the full-length tangent frame the
// renderer needs. A mesh that carries tangents (glTF TANGENT) keeps their directions and
// handedness; others get MikkTSpace-compatible ones (TangentFrames.h).

#include "parallax/Result.h"
#include "parallax/mesh/MeshData.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace px {

// More than this and the preview refuses the mesh (it would take seconds per frame on llvmpipe
// and gigabytes of vertex data): a clear error rather than a hang.
constexpr std::size_t kDefaultMaxMeshTriangles = 2'000'000;

struct MeshLoadOptions {
    int uvSet = 0; // which texture coordinate set carries the material
    std::size_t maxTriangles = kDefaultMaxMeshTriangles;
    // The folder every file the mesh refers to (glTF buffers and images, OBJ material libraries
    // and their textures) must lie under; empty: the mesh's own folder.
    std::string root;
    // Called with 0 to 1 while the file is read; returning false cancels the load.
    std::function<bool(float)> progress;
};

struct LoadedMesh {
    MeshData mesh;
    std::string file;
    int triangles = 0;
    int uvSets = 0;                 // how many the file has
    int uvSet = 0;                  // the one read
    bool fileTangents = false;      // the frames' directions are the file's
    int droppedTriangles = 0;       // zero area in position or uv
    int splitVertices = 0;          // shared by mirrored and unmirrored uv
    float fitScale = 1.0f;          // file units to preview units
    std::vector<std::string> notes; // what the user should know, one sentence each

    std::string summary() const; // "torus.obj: 2048 triangles, uv set 0 of 1, ..."
};

// Errors name the file and the problem: missing or unreadable file, not a mesh, no triangles, no
// uv (or no set `uvSet`), a non-finite position, normal or uv (with the vertex), more triangles
// than the limit, every triangle degenerate, a cancelled load (ErrorKind::Cancelled); before
// Assimp reads anything: a size the file claims but does not hold (GLB chunks, glTF buffers,
// views, accessors), a glTF index past its vertices, a reference outside `root`.
// Degenerate triangles (zero area in position or uv) are dropped and counted in `notes`.
Result<LoadedMesh> loadMesh(const std::string& path, const MeshLoadOptions& options = {});

// The extensions loadMesh reads, lower case with the dot.
bool isMeshFile(const std::string& path);

} // namespace px

#pragma once
// A sculpted tile as the mesh baker reads it: positions in the file's units (node transforms
// applied, nothing centred or scaled), turned Z-up, shading normals where the file has them, and
// triangle indices. The arrays are laid out as Embree reads them, so the ray tracer shares them
// without a copy (docs/conventions.md §8, docs/bakers.md).
//
// Read by Assimp: OBJ, PLY (ASCII and binary), STL, glTF/GLB and FBX. Files that reference others
// (OBJ material libraries, glTF buffers) are confined to the mesh's root as the preview's loader
// confines them (parallax/mesh/MeshLoader.h); sizes are checked against the file before Assimp
// allocates where the format declares them (glTF, OBJ, PLY, STL).

#include "parallax/Result.h"

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace px {

// More than this and the bake refuses the mesh before reading it: a clear error, not a machine
// out of memory (about 1.5 GB of arrays and Embree's hierarchy at the limit).
constexpr std::size_t kMaxBakeTriangles = 20'000'000;

// Which axis of the file points up. Y: read as Blender's top view shows a Y-up file (glTF, most
// FBX): seen from +Y, +X to the right, -Z towards the image top, so (x, y, z) -> (x, -z, y).
enum class MeshUp { Z, Y };

struct BakeMeshLoadOptions {
    MeshUp up = MeshUp::Z;
    std::size_t maxTriangles = kMaxBakeTriangles;
    // The folder every referenced file must lie under; empty: the mesh's own folder.
    std::string root;
    // Called with 0 to 1 while Assimp reads the file; returning false cancels the load.
    std::function<bool(float)> progress;
};

struct BakeMesh {
    std::string file;
    // x, y, z per vertex, then one float of padding: Embree reads the last vertex with a 16-byte
    // load.
    std::vector<float> positions;
    std::vector<float> normals;    // x, y, z per vertex, unit length; empty: face normals only
    std::vector<unsigned> indices; // three per triangle
    glm::vec3 lo{0.0f}, hi{0.0f};  // bounds of the vertices the triangles use
    int droppedTriangles = 0;      // zero area, not handed to the ray tracer
    std::vector<std::string> notes;

    std::size_t vertexCount() const { return positions.size() / 3; }
    std::size_t triangleCount() const { return indices.size() / 3; }
    // Bytes of vertex and index data (the baker's memory bound is stated against it).
    std::size_t dataBytes() const {
        return (positions.size() + normals.size()) * sizeof(float) +
               indices.size() * sizeof(unsigned);
    }
};

// Errors name the file: missing, not a mesh format, unreadable, no triangles, a non-finite
// position or normal (with the vertex), more triangles than the limit, every triangle degenerate,
// a reference outside the root, a size the file claims but does not hold; a cancelled load is
// ErrorKind::Cancelled.
Result<BakeMesh> loadBakeMesh(const std::string& path, const BakeMeshLoadOptions& options = {});

// Builds a BakeMesh from arrays (tests, generated meshes): positions Z-up, normals optional.
BakeMesh makeBakeMesh(const std::vector<glm::vec3>& positions,
                      const std::vector<glm::vec3>& normals, std::vector<unsigned> indices,
                      std::string name = "mesh");

// The extensions loadBakeMesh reads, lower case with the dot.
bool isBakeMeshFile(const std::string& path);

} // namespace px

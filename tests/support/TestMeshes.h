#pragma once
// Meshes the mesh tests generate and write as OBJ, glTF (.gltf + .bin) and GLB, so no third-party
// asset is needed: a torus (with or without glTF tangents), a uv-seamed sphere, a sphere with
// mirrored uv halves, non-uniform scaling (in the vertices or a glTF node's), degenerate triangles,
// a NaN position. uv in glTF's convention (v down the image); the writers convert for OBJ (v up).

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

namespace px::test {

struct TestMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;      // empty: no texture coordinates
    std::vector<glm::vec2> uvs2;     // a second set (glTF TEXCOORD_1), or empty
    std::vector<glm::vec4> tangents; // glTF TANGENT (xyz, handedness w), or empty
    std::vector<unsigned> indices;   // counter-clockwise from outside
    // glTF only: the node's scale, applied by the reader (`scaled` gives what it should read).
    glm::vec3 nodeScale{1.0f};
    // The analytic dP/du and dP/dv at each vertex (for the checks, never written).
    std::vector<glm::vec3> dPdu, dPdv;
};

// Major radius 1, minor 0.4, u three tiles around, v one tile around the tube, unmirrored (the
// image reads upright from outside). With tangents, they are dP/du turned by `tangentTurnDeg`
// about the normal, so a loader that recomputes them can be told from one that keeps them.
TestMesh torus(int rings, int sides, bool withTangents, float tangentTurnDeg = 0.0f);
// Radius 1, u two tiles around with a seam (duplicated vertices) at u = 0 / 2, v pole to pole.
TestMesh seamedSphere(int columns, int rows);
// As seamedSphere, but u runs 0 -> 2 -> 0 around: the halves mirror each other and share the
// vertices on the two mirror meridians (no seam).
TestMesh mirroredSphere(int columns, int rows);
// Positions scaled per axis, normals by the inverse transpose, derivatives by the scale.
TestMesh scaled(TestMesh mesh, glm::vec3 scale);
// Appends three degenerate triangles: a repeated corner, collinear corners, corners with one uv.
TestMesh withDegenerateTriangles(TestMesh mesh);

bool writeObj(const std::string& path, const TestMesh& mesh);
// .gltf with its buffer in FILE.bin beside it, or .glb (one file), by the extension.
bool writeGltf(const std::string& path, const TestMesh& mesh);

} // namespace px::test

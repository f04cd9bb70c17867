#pragma once
// Tangent frames for meshes that have positions, normals and uv: MikkTSpace-compatible directions
// (Mikkelsen, "Simulation of Wrinkled Surfaces Revisited", 2008: the algorithm Blender, Substance
// and the glTF 2.0 specification use to bake and read normal maps), written here from the
// description, at the full length the renderer needs (MeshData.h).
//
// Per triangle, dP/du and dP/dv come from its position and uv edges. At each corner dP/du is
// projected onto the tangent plane of the vertex normal, normalised and weighted by the corner's
// angle; the sums per vertex and per uv orientation are normalised (Gram-Schmidt against the
// normal once more). B is sign * N x T, the sign being the triangles' uv orientation: a vertex
// shared by mirrored and unmirrored triangles is split in two. The lengths |dP/du| and |dP/dv|
// (projected on the tangent plane) are averaged with the same weights: the depth scale follows
// the uv density of the triangles around each vertex and varies smoothly between them.

#include "parallax/mesh/MeshData.h"

#include <optional>

namespace px {

// dP/du and dP/dv of one triangle (uv as stored), or nothing where its uv has no area.
struct TriangleDerivatives {
    glm::vec3 dPdu;
    glm::vec3 dPdv;
    float uvOrientation; // +1 or -1: the sign of the uv area, counter-clockwise corners
};
std::optional<TriangleDerivatives> triangleDerivatives(const MeshVertex& a, const MeshVertex& b,
                                                       const MeshVertex& c);

// glTF's handedness w of a vertex frame: B_glTF = w N x T points up the image (towards smaller v),
// B = dP/dv down it, so w = +1 on an unmirrored mapping (docs/conventions.md §2).
float gltfHandedness(const MeshVertex& v);

// Writes every vertex's tangent and bitangent from the triangles (above); returns how many
// vertices were split because mirrored and unmirrored triangles share them. Every triangle must
// have uv area (the loader drops those that do not).
int generateTangentFrames(MeshData& mesh);

// For meshes that carry their own frames: keeps each vertex's tangent direction and B's side
// (`tangent` and `bitangent` hold the file's directions on entry) and gives them the uv density's
// lengths, averaged as above.
void scaleFramesToUvDensity(MeshData& mesh);

} // namespace px

#pragma once
// The preview meshes, with the tangent frame the shaders need: T = dP/du and B = dP/dv at full
// length (world units per uv unit), N the outward normal (docs/conventions.md §2). uv follows glTF:
// v runs down the image, so on every mesh the image reads upright from outside.
//   plane    2 x 2 in the xz plane, normal +y, u along +x, v along +z
//   cube     side 1.5, each face one tile
//   sphere   radius 1, u around (two tiles, so texels stay about square at the equator), v pole
//            to pole
//   cylinder radius 0.6, height 1.6, two tiles around, caps one tile each

#include "parallax/mesh/MeshData.h"
#include "parallax/render/GlObjects.h"

#include <optional>
#include <span>
#include <string_view>

namespace px {

enum class MeshKind { Plane, Cube, Sphere, Cylinder };

std::span<const std::string_view> meshKindNames();
std::optional<MeshKind> parseMeshKind(std::string_view name);
std::string_view meshKindName(MeshKind kind);

MeshData makeMesh(MeshKind kind);

// A mesh in GL buffers with its vertex array (attributes 0-4 as MeshVertex). Vertex arrays are not
// shared between contexts: make one per context.
class GpuMesh {
public:
    static GpuMesh upload(const MeshData& mesh);
    void draw() const;

private:
    gl::Object m_vertexArray;
    gl::Object m_vertices;
    gl::Object m_indices;
    int m_indexCount = 0;
};

} // namespace px

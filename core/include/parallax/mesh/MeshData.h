#pragma once
// A triangle mesh as the preview draws it, with the tangent frame the shaders need: T = dP/du and
// B = dP/dv at full length (world units per uv unit), N the outward normal (docs/conventions.md
// §2). The lengths set the depth scale: a height scale s in uv units is s * sqrt(|T| |B|) in the
// world, so the relief follows the mesh's uv density.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace px {

struct MeshVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    glm::vec3 tangent;   // dP/du
    glm::vec3 bitangent; // dP/dv
};

struct MeshData {
    std::vector<MeshVertex> vertices;
    std::vector<unsigned> indices; // triangles, counter-clockwise seen from outside
};

} // namespace px

#include "parallax/render/Mesh.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <array>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <numbers>

namespace px {

namespace {

constexpr std::array<std::string_view, 4> kNames{"plane", "cube", "sphere", "cylinder"};

// A flat quad: origin at uv (0, 0), T and B spanning one tile.
void addQuad(MeshData& m, glm::vec3 origin, glm::vec3 T, glm::vec3 B, glm::vec3 normal) {
    const unsigned base = static_cast<unsigned>(m.vertices.size());
    for (int j = 0; j <= 1; ++j) {
        for (int i = 0; i <= 1; ++i) {
            const glm::vec2 uv(i, j);
            m.vertices.push_back({origin + T * uv.x + B * uv.y, normal, uv, T, B});
        }
    }
    // Counter-clockwise seen from the normal's side, whatever the handedness of (T, B).
    const bool flip = glm::dot(glm::cross(T, B), normal) < 0.0f;
    const unsigned a = base, b = base + 1, c = base + 2, d = base + 3;
    const std::array<unsigned, 6> tris = flip ? std::array<unsigned, 6>{a, c, b, b, c, d}
                                              : std::array<unsigned, 6>{a, b, c, b, d, c};
    m.indices.insert(m.indices.end(), tris.begin(), tris.end());
}

// A grid over (s, t) in [0,1]^2; `at` returns the vertex there. Winding as addQuad decides from
// the first cell's frame.
template <typename F> void addGrid(MeshData& m, int columns, int rows, F at) {
    const unsigned base = static_cast<unsigned>(m.vertices.size());
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i <= columns; ++i)
            m.vertices.push_back(at(static_cast<float>(i) / columns, static_cast<float>(j) / rows));
    }
    const MeshVertex& probe =
        m.vertices[base + columns + 2 < m.vertices.size() ? base + columns + 2 : base];
    const bool flip = glm::dot(glm::cross(probe.tangent, probe.bitangent), probe.normal) < 0.0f;
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            const unsigned a = base + j * (columns + 1) + i, b = a + 1, c = a + columns + 1,
                           d = c + 1;
            if (flip)
                m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
            else
                m.indices.insert(m.indices.end(), {a, b, c, b, d, c});
        }
    }
}

MeshData plane() {
    MeshData m;
    addQuad(m, {-1.0f, 0.0f, -1.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 2.0f}, {0.0f, 1.0f, 0.0f});
    return m;
}

MeshData cube() {
    MeshData m;
    const float h = 0.75f, s = 1.5f;
    // Side faces read upright (v down = -y); the top reads upright from the front (+z), the
    // bottom from below with its top edge towards +z.
    addQuad(m, {-h, h, h}, {s, 0, 0}, {0, -s, 0}, {0, 0, 1});   // +z
    addQuad(m, {h, h, h}, {0, 0, -s}, {0, -s, 0}, {1, 0, 0});   // +x
    addQuad(m, {h, h, -h}, {-s, 0, 0}, {0, -s, 0}, {0, 0, -1}); // -z
    addQuad(m, {-h, h, -h}, {0, 0, s}, {0, -s, 0}, {-1, 0, 0}); // -x
    addQuad(m, {-h, h, -h}, {s, 0, 0}, {0, 0, s}, {0, 1, 0});   // +y
    addQuad(m, {-h, -h, h}, {s, 0, 0}, {0, 0, -s}, {0, -1, 0}); // -y
    return m;
}

MeshData sphere() {
    MeshData m;
    const float r = 1.0f, tilesAround = 2.0f;
    // Poles get a tiny offset: a zero-length T would leave the frame undefined there.
    addGrid(m, 64, 32, [&](float s, float t) {
        const float phi = 2.0f * std::numbers::pi_v<float> * s;
        const float theta = std::numbers::pi_v<float> * (1e-4f + t * (1.0f - 2e-4f));
        const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta),
                          std::sin(theta) * std::cos(phi));
        const glm::vec3 T = 2.0f * std::numbers::pi_v<float> * r * std::sin(theta) / tilesAround *
                            glm::vec3(std::cos(phi), 0.0f, -std::sin(phi));
        const glm::vec3 B = std::numbers::pi_v<float> * r *
                            glm::vec3(std::cos(theta) * std::sin(phi), -std::sin(theta),
                                      std::cos(theta) * std::cos(phi));
        return MeshVertex{r * n, n, {tilesAround * s, t}, T, B};
    });
    return m;
}

MeshData cylinder() {
    MeshData m;
    const float r = 0.6f, height = 1.6f, tilesAround = 2.0f;
    addGrid(m, 64, 1, [&](float s, float t) {
        const float phi = 2.0f * std::numbers::pi_v<float> * s;
        const glm::vec3 n(std::sin(phi), 0.0f, std::cos(phi));
        const glm::vec3 T = 2.0f * std::numbers::pi_v<float> * r / tilesAround *
                            glm::vec3(std::cos(phi), 0.0f, -std::sin(phi));
        const glm::vec3 B(0.0f, -height, 0.0f);
        return MeshVertex{{r * n.x, height * (0.5f - t), r * n.z}, n, {tilesAround * s, t}, T, B};
    });
    // Caps: a disc inscribed in one tile.
    for (int side : {1, -1}) {
        const float y = 0.5f * height * side;
        const glm::vec3 normal(0.0f, static_cast<float>(side), 0.0f);
        const glm::vec3 T(2.0f * r, 0.0f, 0.0f);
        const glm::vec3 B(0.0f, 0.0f, side > 0 ? 2.0f * r : -2.0f * r);
        const unsigned centre = static_cast<unsigned>(m.vertices.size());
        m.vertices.push_back({{0.0f, y, 0.0f}, normal, {0.5f, 0.5f}, T, B});
        const int segments = 64;
        for (int i = 0; i <= segments; ++i) {
            const float phi = 2.0f * std::numbers::pi_v<float> * i / segments;
            const glm::vec3 p(r * std::sin(phi), y, r * std::cos(phi));
            const glm::vec2 uv(0.5f + p.x / (2.0f * r),
                               0.5f + (side > 0 ? p.z : -p.z) / (2.0f * r));
            m.vertices.push_back({p, normal, uv, T, B});
        }
        for (int i = 0; i < segments; ++i) {
            const unsigned a = centre + 1 + i, b = a + 1;
            // Seen from outside the rim runs counter-clockwise with increasing phi on the top.
            if (side > 0)
                m.indices.insert(m.indices.end(), {centre, a, b});
            else
                m.indices.insert(m.indices.end(), {centre, b, a});
        }
    }
    return m;
}

} // namespace

std::span<const std::string_view> meshKindNames() {
    return kNames;
}

std::optional<MeshKind> parseMeshKind(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i) {
        if (kNames[i] == name)
            return static_cast<MeshKind>(i);
    }
    return std::nullopt;
}

std::string_view meshKindName(MeshKind kind) {
    return kNames.at(static_cast<std::size_t>(kind));
}

MeshData makeMesh(MeshKind kind) {
    switch (kind) {
    case MeshKind::Plane:
        return plane();
    case MeshKind::Cube:
        return cube();
    case MeshKind::Sphere:
        return sphere();
    case MeshKind::Cylinder:
        return cylinder();
    }
    return plane();
}

GpuMesh GpuMesh::upload(const MeshData& mesh) {
    GpuMesh g;
    g.m_vertexArray = gl::Object(gl::ObjectKind::VertexArray);
    g.m_vertices = gl::Object(gl::ObjectKind::Buffer);
    g.m_indices = gl::Object(gl::ObjectKind::Buffer);
    g.m_indexCount = static_cast<int>(mesh.indices.size());
    glBindVertexArray(g.m_vertexArray.id());
    glBindBuffer(GL_ARRAY_BUFFER, g.m_vertices.id());
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(MeshVertex)),
                 mesh.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.m_indices.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(unsigned)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    auto attribute = [](GLuint index, int size, std::size_t offset) {
        glEnableVertexAttribArray(index);
        glVertexAttribPointer(
            index, size, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
            // GL takes a buffer offset as a pointer
            reinterpret_cast<const void*>(offset)); // NOLINT(performance-no-int-to-ptr)
    };
    attribute(0, 3, offsetof(MeshVertex, position));
    attribute(1, 3, offsetof(MeshVertex, normal));
    attribute(2, 2, offsetof(MeshVertex, uv));
    attribute(3, 3, offsetof(MeshVertex, tangent));
    attribute(4, 3, offsetof(MeshVertex, bitangent));
    glBindVertexArray(0);
    return g;
}

void GpuMesh::draw() const {
    glBindVertexArray(m_vertexArray.id());
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

} // namespace px

#include "parallax/mesh/TangentFrames.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace px {

namespace {

// What the corners around one vertex (and one uv orientation) contribute.
struct Accumulator {
    glm::vec3 tangent{0.0f};
    float lengthU = 0.0f;
    float lengthV = 0.0f;
    float weight = 0.0f;
};

glm::vec3 projected(glm::vec3 v, glm::vec3 n) {
    return v - n * glm::dot(n, v);
}

glm::vec3 unit(glm::vec3 v) {
    const float len = glm::length(v);
    return len > 0.0f ? v / len : glm::vec3(0.0f);
}

// The corner's angle between its edges projected on the vertex's tangent plane, as MikkTSpace
// weighs corners: a vertex's frame does not depend on how finely its fan is cut.
float cornerAngle(glm::vec3 at, glm::vec3 p1, glm::vec3 p2, glm::vec3 n) {
    const glm::vec3 e1 = unit(projected(p1 - at, n)), e2 = unit(projected(p2 - at, n));
    return std::acos(std::clamp(glm::dot(e1, e2), -1.0f, 1.0f));
}

// Any unit vector in the plane of n, for a vertex whose corners all had dP/du along n.
glm::vec3 anyPerpendicular(glm::vec3 n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return unit(glm::cross(n, axis));
}

// Adds each triangle's corners to accumulators[slot(vertex, triangle orientation)].
template <typename Slot>
void accumulate(const MeshData& mesh, std::vector<Accumulator>& accumulators, Slot slot) {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const unsigned corner[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
        const std::optional<TriangleDerivatives> d = triangleDerivatives(
            mesh.vertices[corner[0]], mesh.vertices[corner[1]], mesh.vertices[corner[2]]);
        if (!d)
            continue;
        for (int k = 0; k < 3; ++k) {
            const MeshVertex& v = mesh.vertices[corner[k]];
            const glm::vec3 n = unit(v.normal);
            const glm::vec3 t = projected(d->dPdu, n);
            const float weight =
                cornerAngle(v.position, mesh.vertices[corner[(k + 1) % 3]].position,
                            mesh.vertices[corner[(k + 2) % 3]].position, n);
            Accumulator& a = accumulators[slot(corner[k], d->uvOrientation)];
            a.tangent += weight * unit(t);
            a.lengthU += weight * glm::length(t);
            a.lengthV += weight * glm::length(projected(d->dPdv, n));
            a.weight += weight;
        }
    }
}

} // namespace

std::optional<TriangleDerivatives> triangleDerivatives(const MeshVertex& a, const MeshVertex& b,
                                                       const MeshVertex& c) {
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 0.0f) || !std::isfinite(1.0f / det))
        return std::nullopt;
    return TriangleDerivatives{(e1 * d2.y - e2 * d1.y) / det, (e2 * d1.x - e1 * d2.x) / det,
                               det > 0.0f ? 1.0f : -1.0f};
}

float gltfHandedness(const MeshVertex& v) {
    return glm::dot(glm::cross(v.normal, v.tangent), v.bitangent) > 0.0f ? -1.0f : 1.0f;
}

int generateTangentFrames(MeshData& mesh) {
    const std::size_t count = mesh.vertices.size();
    // Two slots per vertex, one per uv orientation (the sign of the uv area; with v down the
    // image an unmirrored mapping has negative area).
    std::vector<Accumulator> sums(2 * count);
    accumulate(mesh, sums, [](unsigned v, float orientation) {
        return 2 * static_cast<std::size_t>(v) + (orientation < 0.0f ? 1 : 0);
    });

    // A vertex both orientations use gets a twin for the negative ones.
    std::vector<unsigned> twin(count);
    int split = 0;
    for (std::size_t v = 0; v < count; ++v) {
        twin[v] = static_cast<unsigned>(v);
        if (sums[2 * v].weight > 0.0f && sums[2 * v + 1].weight > 0.0f) {
            twin[v] = static_cast<unsigned>(mesh.vertices.size());
            mesh.vertices.push_back(mesh.vertices[v]);
            ++split;
        }
    }
    if (split > 0) {
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const std::optional<TriangleDerivatives> d = triangleDerivatives(
                mesh.vertices[mesh.indices[i]], mesh.vertices[mesh.indices[i + 1]],
                mesh.vertices[mesh.indices[i + 2]]);
            if (d && d->uvOrientation < 0.0f) {
                for (int k = 0; k < 3; ++k)
                    mesh.indices[i + k] = twin[mesh.indices[i + k]];
            }
        }
    }

    for (std::size_t v = 0; v < count; ++v) {
        for (int side = 0; side < 2; ++side) {
            const Accumulator& a = sums[2 * v + side];
            if (a.weight <= 0.0f)
                continue;
            MeshVertex& out = mesh.vertices[side == 0 ? v : twin[v]];
            const glm::vec3 n = unit(out.normal);
            glm::vec3 t = unit(projected(a.tangent, n));
            if (glm::length(t) == 0.0f)
                t = anyPerpendicular(n);
            // dP/dv lies on N x T's side where the uv area is positive: e1 x e2 = (T x B) det.
            const float sign = side == 0 ? 1.0f : -1.0f;
            out.tangent = t * (a.lengthU / a.weight);
            out.bitangent = sign * glm::cross(n, t) * (a.lengthV / a.weight);
        }
    }
    return split;
}

void scaleFramesToUvDensity(MeshData& mesh) {
    std::vector<Accumulator> sums(mesh.vertices.size());
    accumulate(mesh, sums, [](unsigned v, float) { return static_cast<std::size_t>(v); });
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const Accumulator& a = sums[v];
        if (a.weight <= 0.0f)
            continue;
        MeshVertex& out = mesh.vertices[v];
        out.tangent = unit(out.tangent) * (a.lengthU / a.weight);
        out.bitangent = unit(out.bitangent) * (a.lengthV / a.weight);
    }
}

} // namespace px

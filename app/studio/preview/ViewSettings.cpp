#include "preview/ViewSettings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <vector>

namespace px::studio {

namespace {

// The mesh leaves this much of the view around it.
constexpr float kFrameMargin = 1.08f;
// The vertices the framing projects: every one of a small mesh, evenly spread ones of a big one.
constexpr std::size_t kFramePoints = 8192;

const MeshData& meshOf(const SharedView& view) {
    if (view.meshData)
        return *view.meshData;
    static const std::array<MeshData, 4> builtIn = [] {
        std::array<MeshData, 4> meshes;
        for (std::size_t k = 0; k < meshes.size(); ++k)
            meshes[k] = makeMesh(static_cast<MeshKind>(k));
        return meshes;
    }();
    return builtIn.at(static_cast<std::size_t>(view.mesh));
}

// Whether every point is in front of `camera` and within 1 / kFrameMargin of the view's centre.
bool fits(const OrbitCamera& camera, float aspect, const std::vector<glm::vec3>& points) {
    const glm::mat4 m = camera.projection(aspect) * camera.view();
    const float limit = 1.0f / kFrameMargin;
    return std::ranges::all_of(points, [&](const glm::vec3& p) {
        const glm::vec4 clip = m * glm::vec4(p, 1.0f);
        return clip.w > 0.0f && std::abs(clip.x) <= limit * clip.w &&
               std::abs(clip.y) <= limit * clip.w && std::abs(clip.z) <= clip.w;
    });
}

} // namespace

OrbitCamera defaultCamera() {
    OrbitCamera camera;
    camera.azimuthDeg = 20.0f;
    camera.elevationDeg = 32.0f;
    camera.distance = 2.1f;
    return camera;
}

float meshRadius(const SharedView& view) {
    float r = 0.0f;
    for (const MeshVertex& v : meshOf(view).vertices)
        r = std::max(r, glm::length(v.position));
    return r;
}

OrbitCamera framed(OrbitCamera camera, const SharedView& view, float aspect) {
    camera.target = glm::vec3(0.0f);
    if (!view.meshData && view.mesh == MeshKind::Plane) {
        camera.distance = defaultCamera().distance;
        return camera;
    }
    // From the bounding sphere's distance (r / sin a: whole from any angle) in, as close as the
    // mesh seen from these angles stays whole: it fills the view.
    const float halfY = glm::radians(camera.fovYDeg) / 2.0f;
    const float halfX = std::atan(std::tan(halfY) * std::max(aspect, 1e-3f));
    const float sphere = kFrameMargin * meshRadius(view) / std::sin(std::min(halfX, halfY));
    const std::vector<MeshVertex>& vertices = meshOf(view).vertices;
    const std::size_t stride = std::max<std::size_t>(1, vertices.size() / kFramePoints);
    std::vector<glm::vec3> points;
    points.reserve(vertices.size() / stride + 1);
    for (std::size_t i = 0; i < vertices.size(); i += stride)
        points.push_back(vertices[i].position);
    float near = 0.0f, far = sphere; // far fits, near does not
    for (int i = 0; i < 24; ++i) {
        camera.distance = 0.5f * (near + far);
        (fits(camera, aspect, points) ? far : near) = camera.distance;
    }
    camera.distance = far;
    return camera;
}

} // namespace px::studio

#pragma once
// The preview's orbit camera and directional light. World: y up. Angles: azimuth about +y from +z
// towards +x, elevation above the xz plane, both in degrees; a direction (azimuth, elevation)
// points from the origin towards (cos el sin az, sin el, cos el cos az). So azimuth 0 looks at the
// front (+z) of every mesh, and a light at (az, el) shines from that direction.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace px {

glm::vec3 directionFromAngles(float azimuthDeg, float elevationDeg);

struct OrbitCamera {
    float azimuthDeg = 30.0f;
    float elevationDeg = 35.0f; // kept inside (-89.9, 89.9) by position()
    float distance = 3.4f;
    glm::vec3 target{0.0f};
    float fovYDeg = 40.0f;

    glm::vec3 position() const;
    glm::mat4 view() const;
    // Near and far planes follow the distance, so any orbit keeps depth precision.
    glm::mat4 projection(float aspect) const;
};

struct DirectionalLight {
    float azimuthDeg = 135.0f;
    float elevationDeg = 40.0f;
    glm::vec3 color{1.0f};
    float ambient = 0.12f;

    // Unit vector towards the light.
    glm::vec3 direction() const { return directionFromAngles(azimuthDeg, elevationDeg); }
};

} // namespace px

#include "parallax/render/Camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace px {

glm::vec3 directionFromAngles(float azimuthDeg, float elevationDeg) {
    const float az = glm::radians(azimuthDeg);
    const float el = glm::radians(elevationDeg);
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

glm::vec3 OrbitCamera::position() const {
    return target + std::max(distance, 1e-3f) *
                        directionFromAngles(azimuthDeg, std::clamp(elevationDeg, -89.9f, 89.9f));
}

glm::mat4 OrbitCamera::view() const {
    return glm::lookAt(position(), target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    const float d = std::max(distance, 1e-3f);
    return glm::perspective(glm::radians(fovYDeg), aspect, 0.02f * d, 10.0f * d);
}

} // namespace px

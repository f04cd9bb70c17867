#include "preview/ViewInteraction.h"

#include <algorithm>
#include <cmath>

namespace px::studio {

namespace {
float wrapDegrees(float a) {
    a = std::fmod(a + 180.0f, 360.0f);
    return (a < 0 ? a + 360.0f : a) - 180.0f;
}
} // namespace

OrbitCamera orbit(const OrbitCamera& camera, QPointF delta) {
    OrbitCamera c = camera;
    c.azimuthDeg = wrapDegrees(c.azimuthDeg - static_cast<float>(delta.x()) * kDegreesPerPixel);
    c.elevationDeg = std::clamp(c.elevationDeg + static_cast<float>(delta.y()) * kDegreesPerPixel,
                                kMinElevation, kMaxElevation);
    return c;
}

OrbitCamera withPolarAngle(const OrbitCamera& camera, double polarDeg) {
    OrbitCamera c = camera;
    c.elevationDeg = std::clamp(90.0f - static_cast<float>(polarDeg), kMinElevation, kMaxElevation);
    return c;
}

OrbitCamera zoom(const OrbitCamera& camera, double steps) {
    OrbitCamera c = camera;
    c.distance = std::clamp(c.distance * static_cast<float>(std::pow(0.9, steps)), kMinDistance,
                            kMaxDistance);
    return c;
}

DirectionalLight moveLight(const DirectionalLight& light, QPointF delta) {
    DirectionalLight l = light;
    l.azimuthDeg = wrapDegrees(l.azimuthDeg + static_cast<float>(delta.x()) * kDegreesPerPixel);
    l.elevationDeg =
        std::clamp(l.elevationDeg - static_cast<float>(delta.y()) * kDegreesPerPixel, 1.0f, 90.0f);
    return l;
}

} // namespace px::studio

#include "ViewSettings.h"

namespace px::studio {

OrbitCamera defaultCamera() {
    OrbitCamera camera;
    camera.azimuthDeg = 20.0f;
    camera.elevationDeg = 38.0f;
    camera.distance = 2.6f;
    return camera;
}

} // namespace px::studio

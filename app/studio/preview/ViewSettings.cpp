#include "preview/ViewSettings.h"

namespace px::studio {

OrbitCamera defaultCamera() {
    OrbitCamera camera;
    camera.azimuthDeg = 20.0f;
    camera.elevationDeg = 32.0f;
    camera.distance = 2.1f;
    return camera;
}

} // namespace px::studio

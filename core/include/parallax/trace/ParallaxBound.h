#pragma once
// What the kernels do with a view's parallax vector P (pxBoundParallax in
// shaders/trace/common.glsl): a grazing view's |P| is bounded to 10^4 uv by its length, so the
// direction (the azimuth) is kept, and NaN becomes a straight-down view. The command line says
// so when it happens.

#include <glm/vec2.hpp>
#include <string>

namespace px {

struct BoundedParallax {
    glm::vec2 P{0.0f};
    std::string note; // empty, or a sentence saying the view was shortened and to what
};

BoundedParallax boundParallax(glm::vec2 P);

} // namespace px

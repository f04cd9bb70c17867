#include "parallax/trace/ParallaxBound.h"

#include "TraceKernel.h"

#include <cmath>
#include <cstdio>

namespace px {

BoundedParallax boundParallax(glm::vec2 P) {
    kernel::TraceKernel k;
    BoundedParallax b;
    b.P = k.pxBoundParallax(P);
    if (b.P != P && !(std::isnan(P.x) || std::isnan(P.y))) {
        const double given = std::hypot(static_cast<double>(P.x), static_cast<double>(P.y));
        const double kept = std::hypot(static_cast<double>(b.P.x), static_cast<double>(b.P.y));
        char text[200];
        std::snprintf(text, sizeof text,
                      "the view's parallax |P| = %.4g uv is over the bound of %.4g: its rays are "
                      "shortened to that length, in the same direction",
                      given, kept);
        b.note = text;
    } else if (std::isnan(P.x) || std::isnan(P.y)) {
        b.note = "the view's parallax has a NaN component: it counts as 0";
    }
    return b;
}

} // namespace px

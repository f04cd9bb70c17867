#pragma once
// The exact hit of a ray in double precision: the cell walk and the ray/bilinear-patch quadratic
// of docs/conventions.md §2, written independently of the float kernels, so tests can tell how much
// of a kernel's answer float32 costs on long, grazing rays.

#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <glm/vec2.hpp>

namespace px::test {

// t of the first hit of uv(t) = uv0 + P t, z = 1 - t, for t >= max(0, 1 - highest texel); 1 if
// none before (the bottom is solid).
double doubleWalkT(const HeightField& field, WrapMode wrap, glm::dvec2 uv0, glm::dvec2 P);

} // namespace px::test

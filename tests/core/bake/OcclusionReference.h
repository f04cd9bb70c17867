#pragma once
// An occlusion reference that shares nothing with the baker (docs/conventions.md §7): every cell
// boundary the ray crosses is listed, the height between two crossings is fitted as a quadratic
// from three bilinear samples, the best secant is solved from that quadratic, and the elevation
// integrals are Gauss-Legendre quadratures rather than closed forms.

#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"

#include <glm/glm.hpp>

namespace px::test {

struct OcclusionReferenceSettings {
    double scale = 0.05;
    double distance = 0.25; // uv; +inf: unlimited (repeat: out to `openReach` tiles)
    WrapMode wrap = WrapMode::Repeat;
    int azimuths = 256;
    double openReach = 64.0;
};

// The horizon's tangent from texel (x, y) along (cos phi, sin phi) in (X, Y) = (u, -v).
double referenceHorizon(const HeightField& field, const OcclusionReferenceSettings& settings, int x,
                        int y, double phi);

struct ReferenceOcclusion {
    double ao = 1.0;
    glm::dvec3 bent{0.0, 0.0, 1.0}; // unit, (X, Y, Z) = (u, -v, up)
};

ReferenceOcclusion referenceOcclusion(const HeightField& field,
                                      const OcclusionReferenceSettings& settings, int x, int y);

} // namespace px::test

#pragma once
// Image-based light by the split sum (Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013):
// the specular integral under GGX is split into the environment prefiltered per roughness and a
// 2D table of the BRDF's scale and bias on F0; diffuse light is the irradiance, kept as nine
// spherical-harmonic coefficients (Ramamoorthi and Hanrahan, "An Efficient Representation for
// Irradiance Environment Maps", 2001). Computed here on the CPU once per environment, uploaded
// by the renderer; shaders/render/lighting.glsl reads them.

#include "parallax/image/Image.h"

#include <array>
#include <glm/vec3.hpp>
#include <vector>

namespace px {

// Coefficients of E(n) / pi, the diffuse radiance of a white Lambert surface facing n: in the
// real SH basis (1; y, z, x; xy, yz, 3z^2 - 1, xz, x^2 - y^2), the band weights already applied.
using IrradianceSh = std::array<glm::vec3, 9>;

struct PrefilteredEnvironment {
    IrradianceSh irradiance{};
    // Level i holds the environment convolved with GGX at roughness i / (levels - 1) (level 0 is
    // the mirror image), width base >> i; the renderer uploads them as one texture's mip chain.
    std::vector<Image> specular;
};

// `map` as loadEnvironment or makeSkyEnvironment make it (RGB, 2:1).
PrefilteredEnvironment prefilterEnvironment(const Image& map, int baseWidth = 256, int levels = 6);

// E(n) / pi from the coefficients, as the shader evaluates it.
glm::vec3 irradianceAt(const IrradianceSh& sh, glm::vec3 n);

// The split sum's second factor: for N.V (x) and roughness (y) at texel centres, (A, B) with
// specular = prefiltered * (F0 A + B); Smith-Schlick visibility with k = roughness^2 / 2.
Image makeSplitSumTable(int size = 32, int samples = 512);

} // namespace px

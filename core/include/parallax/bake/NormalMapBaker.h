#pragma once
// Tangent-space normal maps from a height map (docs/conventions.md §3), and loaded normal maps
// passed through with their green channel converted.
//
// A baked normal describes the displaced surface z = s h at the material's height scale s:
// n ∝ (-s dh/du, +s dh/dv, 1), dh/du and dh/dv in uv units. Each filter is a derivative estimate
// that is exact on a linear ramp, so the filter changes smoothing, never strength, and normal
// mapping agrees with parallax by construction.

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/NormalGreen.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace px {

enum class NormalFilter {
    Central, // 4 taps: (h(x+1) - h(x-1)) / 2
    Sobel,   // 3x3, rows weighted 1 2 1 (divides by 8)
    Scharr,  // 3x3, rows weighted 3 10 3 (divides by 32): the most rotation-invariant
};

std::string_view toString(NormalFilter filter); // "central", "sobel", "scharr"
std::optional<NormalFilter> parseNormalFilter(std::string_view name);
std::span<const std::string_view> normalFilterNames();

struct NormalBakeOptions {
    float heightScale = 0.05f; // s, uv units: the material's height_scale (0 gives flat normals)
    NormalFilter filter = NormalFilter::Sobel;
    // repeat: derivatives wrap, so a tiling height map gives a tiling normal map;
    // clamp: edge texels use the taps inside the map, divided by their real distance.
    WrapMode wrap = WrapMode::Repeat;
    NormalGreen green = NormalGreen::OpenGL; // DirectX (Y-) flips green
};

// Returns a 3-channel image holding n * 0.5 + 0.5 (linear, unit n), ready to write or upload.
// Errors: an empty height field, a negative or non-finite height scale, cancellation.
Result<Image> bakeNormalMap(const HeightField& field, const NormalBakeOptions& options,
                            const BakeControl& control = {});

// A loaded normal map (n * 0.5 + 0.5 in R, G, B; or R, G only, with B rebuilt from unit length)
// converted from one green convention to the other, otherwise unchanged: flipping green is
// 1 - G, exact at every bit depth. `source` names the file in errors (fewer than two channels).
Result<Image> convertNormalMap(const Image& normals, NormalGreen from, NormalGreen to,
                               const std::string& source);

// Pearson correlations of a normal map (n * 0.5 + 0.5) with the slopes of a height map (white =
// high) at the normal map's texel centres: red with -dh/du ("across") and green with +dh/dv
// ("down"). Both are positive for the map's own normal map under OpenGL green; a depth map flips
// both, DirectX green flips "down". 0 where either side is constant; sizes may differ.
struct SlopeCorrelation {
    double across = 0.0;
    double down = 0.0;
};
SlopeCorrelation correlateWithSlopes(const Image& normals, const HeightField& field, WrapMode wrap);

// Tells a loaded normal map's green convention from the height map it belongs to: under the right
// convention its green correlates positively with the height map's slope (docs/conventions.md §3).
// Sizes may differ. Errors name `source`: too few channels, or no slope to tell by (a flat map).
Result<NormalGreen> detectNormalGreen(const Image& normals, const HeightField& field, WrapMode wrap,
                                      const std::string& source);

} // namespace px

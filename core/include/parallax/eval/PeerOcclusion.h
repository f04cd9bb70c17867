#pragma once
// The occlusion methods other tools publish, written here from their descriptions so that their
// error against the exact value (parallax/bake/OcclusionBaker.h) can be measured on the same
// surface (docs/bakers.md, "Occlusion: error against cost"). Not for production: the exact baker
// is cheaper at equal error. Every method reads the surface as the exact one does
// (docs/conventions.md §7): z = s h, h bilinear between texel centres, the material's wrap, X = u,
// Y = -v, lengths in uv units, the central-filter normal; and returns one grey channel, 1 =
// unoccluded. On a flat map every one gives exactly 1.

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"

#include <limits>

namespace px {

// The surface every method reads.
struct PeerSurfaceOptions {
    float heightScale = 0.05f; // s, uv units
    WrapMode wrap = WrapMode::Repeat;
};

// Horizon-based AO (Bavoil, Sainz and Dimitrov 2008), as Material Maker (8 directions x 4 steps,
// radius 0.1 uv, angle bias 15 degrees) and Substance Designer's HBAO node (quality 4, 8, 16)
// run it: per direction, steps out to `radius`; each rise of the horizon above the tangent plane
// (raised by the bias) adds (sin h - sin h_before) weighted by 1 - r^2 / radius^2; AO = 1 - the
// mean over directions. A uniform, not cosine, weighting, and sampled horizons.
struct HbaoOptions {
    int directions = 8;
    int steps = 4;
    double radius = 0.1; // uv
    double angleBiasDeg = 15.0;
};

// Materialize's heuristic: per direction, the largest sin(elevation) x saturate(0.1 x distance in
// texels) over `steps` samples out to `reachTexels`; AO = 1 - the mean over directions. Elevation
// is above the horizontal, not the tangent plane, so a tilted plane is darkened.
struct MaxOfSineOptions {
    int directions = 99;
    int steps = 50;
    double reachTexels = 50.0;
};

// AwesomeBump-style screen-space sum: the mean of max(0, n . v/|v|) over the (2N+1)^2 - 1 grid
// neighbours (spaced `spacingTexels` apart) around the texel, v from the texel's point to the
// neighbour's; AO = 1 - that mean. No horizons: a blocker behind another still counts.
struct SsaoSumOptions {
    int radius = 4; // N
    double spacingTexels = 1.0;
};

// A Monte Carlo ray cast: `rays` directions drawn uniformly over the hemisphere about n (a fixed
// sequence per texel from `seed`), each marched over the height field in steps of `stepTexels`
// texels until it is below the surface (blocked), beyond `distance` or above the highest texel;
// AO = sum(V cos) / sum(cos), so a flat map is exactly 1. Unlimited distance is cut at 4 tiles.
struct RayMarchOptions {
    int rays = 64;
    double distance = std::numeric_limits<double>::infinity(); // horizontal, uv
    double stepTexels = 0.5;
    unsigned seed = 1;
};

// Errors: an empty field, a negative or non-finite height scale, counts below 1, a radius,
// reach, spacing, step or distance that is not > 0, cancellation. Every core (TBB).
Result<Image> hbaoOcclusion(const HeightField& field, const PeerSurfaceOptions& surface,
                            const HbaoOptions& options, const BakeControl& control = {});
Result<Image> maxOfSineOcclusion(const HeightField& field, const PeerSurfaceOptions& surface,
                                 const MaxOfSineOptions& options, const BakeControl& control = {});
Result<Image> ssaoSumOcclusion(const HeightField& field, const PeerSurfaceOptions& surface,
                               const SsaoSumOptions& options, const BakeControl& control = {});
Result<Image> rayMarchOcclusion(const HeightField& field, const PeerSurfaceOptions& surface,
                                const RayMarchOptions& options, const BakeControl& control = {});

} // namespace px

#pragma once
// Ambient occlusion and bent normals from a height map (docs/conventions.md §7), exact but for the
// number of azimuths: in each azimuth the horizon of the bilinear surface z = s h is found exactly
// (the r -> 0+ limit, the point's own slope, included, so a plane is never occluded) and the
// cosine-weighted integral above it is closed-form (the GTAO inner integral). Both results come
// from the same horizons, so one bake can give both.
//
//   OcclusionBakeOptions options;
//   options.heightScale = material.heightScale;
//   options.wrap = material.wrap;
//   Result<OcclusionMaps> maps = bakeOcclusion(field, options, OcclusionOutputs::Both, control);

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/NormalGreen.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"

#include <limits>

namespace px {

// The azimuth count a bake uses when the options ask for 0: within 0.5/255 mean and 2/255 at
// p99.9 of the many-azimuth value on every map tested (docs/bakers.md).
inline constexpr int kDefaultOcclusionDirections = 64;
// The most azimuths a bake accepts (more changes nothing measurable and only costs time).
inline constexpr int kMaxOcclusionDirections = 4096;

struct OcclusionBakeOptions {
    float heightScale = 0.05f; // s, uv units: the material's height_scale (0: AO = 1 everywhere)
    // D: the horizontal uv distance a blocker may be at. +inf: unlimited (every tile of a repeating
    // surface, the sky as the environment light sees it); a finite D is the artist's spread.
    double distance = std::numeric_limits<double>::infinity();
    int directions =
        0; // azimuths, evenly spaced, the first along +X; 0: kDefaultOcclusionDirections
    WrapMode wrap = WrapMode::Repeat;        // repeat tiles the surface, clamp extends the edges
    NormalGreen green = NormalGreen::OpenGL; // the bent normals' green (DirectX: Y-, 1 - G)
};

enum class OcclusionOutputs { AmbientOcclusion, BentNormals, Both };

struct OcclusionMaps {
    // One channel, linear, 1 = unoccluded, 0 = fully occluded (empty unless asked for).
    Image occlusion;
    // Three channels, n * 0.5 + 0.5 of the unit bent normal, green as the options say (empty
    // unless asked for). Where nothing is visible (never on a height field) it is the normal.
    Image bentNormals;
};

// Errors: an empty height field, a negative or non-finite height scale, a distance that is not
// > 0 (NaN included), directions outside [0, kMaxOcclusionDirections], cancellation
// (cancelledError(): nothing is returned). Uses every core (TBB).
Result<OcclusionMaps> bakeOcclusion(const HeightField& field, const OcclusionBakeOptions& options,
                                    OcclusionOutputs outputs, const BakeControl& control = {});

// The azimuth count `options` resolves to (0 -> the default).
int occlusionDirections(const OcclusionBakeOptions& options);

} // namespace px

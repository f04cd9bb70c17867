#pragma once
// Colour maps for the built-in sample materials, made from their own height fields so colour and
// relief always line up (mortar in the grooves, tinted bricks on the faces). Deterministic for a
// given height field and seed; no third-party art.

#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"
#include "parallax/sample/ProceduralMaps.h"

namespace px {

// An RGB image the size of `field`, holding sRGB-encoded values in [0, 1] (docs/conventions.md §6).
// Bricks, stones and rivets get a material look (mortar and tinted bricks, earth and cobbles,
// steel and rivet heads, each raised region its own tint); the test shapes a neutral stone ramp.
// `wrap` decides whether raised regions continue across the tile's edges.
Image makeProceduralAlbedo(ProceduralMap kind, const HeightField& field, unsigned seed = 1,
                           WrapMode wrap = WrapMode::Repeat);

// The raised regions of a height field: texels above `threshold` connected through their four
// neighbours (across the edges with repeat), numbered from 1 in scan order; 0 below the threshold.
std::vector<int> labelRaisedRegions(const HeightField& field, float threshold, WrapMode wrap);

} // namespace px

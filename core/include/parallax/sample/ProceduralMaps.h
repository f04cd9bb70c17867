#pragma once
// Height fields the project makes itself: the built-in sample materials (no third-party art) and
// the shapes the tests and the stability suite need. Deterministic for a given size and seed.

#include "parallax/heightfield/HeightField.h"

#include <optional>
#include <span>
#include <string_view>

namespace px {

enum class ProceduralMap {
    Bricks,  // mortar lines, bevelled bricks, a little grain
    Stones,  // rounded cobbles (Voronoi cells)
    Rivets,  // a plate of hemispherical rivets
    Noise,   // smooth value noise, several octaves
    Random,  // independent uniform texels (the stiffest case for every technique)
    Ramp,    // h = u, a linear ramp across the tile
    Checker, // 0/1 checkerboard of single texels
    Spikes,  // sparse single-texel needles of height 1 on 0
    Step,    // left half 0, right half 1: a vertical step
    Cracks,  // flat 1 with thin one-texel cracks down to 0
    Flat,    // constant `level`
    // Made to break tracers (AdversarialMaps.cpp), positions and heights from the seed:
    SpikeFlat, // a low flat along each row with one single-texel spike to the top
    Walls,     // one-texel walls every second column (the Nyquist rate), random heights
    Treads,    // stairs along u with long treads (8 to 32 texels)
    Pits,      // the top pierced by isolated one-texel pits to the bottom
    Terraces,  // smooth hills cut into six terraces, 8-bit quantised
    Outliers,  // gentle low noise and six single texels at the top
    Jpeg,      // hills and grain, 8 bits, through a JPEG codec at quality 75
};

std::span<const std::string_view> proceduralMapNames();
std::optional<ProceduralMap> parseProceduralMap(std::string_view name);

HeightField makeProceduralMap(ProceduralMap kind, int width, int height, unsigned seed = 1,
                              float level = 0.5f);

} // namespace px

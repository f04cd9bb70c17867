#pragma once
// Batch export: a folder of height maps, found by suffix (docs/conventions.md §6), each turned into
// a material with one preset's settings and the sibling maps that share its base name.

#include "parallax/Result.h"
#include "parallax/material/Material.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace px {

struct BatchItem {
    std::string name;       // the base name: "bricks" for bricks_height.png
    std::string heightFile; // the height map that started it
    Material material;      // the preset with this item's maps (absolute paths) and name
    std::string problem;    // non-empty: this item cannot be exported (e.g. a second height map)
};

// The suffixes that mark a height map; "_depth" marks a depth map (loaded inverted).
std::span<const std::string_view> heightSuffixes();

// Every height map in `folder` (not recursive), sorted by name, with its siblings: albedo
// (_albedo _diffuse _basecolor _color), normal (_normal _nrm _n), ao (_ao _occlusion),
// _roughness, _metallic; suffixes and extensions matched without regard to case. Errors: the
// folder is missing or unreadable.
Result<std::vector<BatchItem>> scanBatchFolder(const std::string& folder, const Material& preset);

} // namespace px

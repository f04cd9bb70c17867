#pragma once
// The material file: versioned JSON that the editor opens and saves, the command line reads and
// the exports write.
//
//   {
//     "format": "parallax-studio-material", "version": 1,
//     "name": "bricks",
//     "maps": { "albedo": "bricks_albedo.png", "height": "bricks_height.png" },
//     "height": { "channel": "red", "invert": false, "scale": 0.05 },
//     "wrap": "repeat", "tiling": 1,
//     "technique": { "name": "pom", "minLayers": 8, "maxLayers": 32, "binarySteps": 6,
//                    "secantSteps": 3, "maxSteps": 64 },
//     "normal": { "source": "height-central", "green": "opengl" },
//     "shadow": { "enabled": false, "softness": 0.5 },
//     "lighting": { "model": "blinn-phong", "roughness": 0.6, "metallic": 0, "specular": 0.3,
//                   "shininess": 32 }
//   }
//
// Map paths are relative to the file's folder (or absolute), '/'-separated. Everything but
// "format" and "version" may be left out and takes the defaults of Material.h (technique
// parameters: that technique's defaults). Unknown keys are errors, not silently ignored: a typo
// must not quietly fall back to a default. A newer version is refused, never misread.

#include "parallax/Result.h"
#include "parallax/material/Material.h"

#include <string>
#include <string_view>
#include <vector>

namespace px {

inline constexpr std::string_view kMaterialFormat = "parallax-studio-material";
inline constexpr int kMaterialVersion = 1;

// One problem with a material, at a JSON pointer ("/technique/maxLayers"; "" for the whole file).
struct MaterialProblem {
    std::string pointer;
    std::string message;
};

// What a material must have to be valid.
enum class MaterialCheck {
    Complete, // a material to render: the maps its technique and normal source read are named
    Preset,   // settings to apply to other maps (batch export): maps may be absent
};

// The value checks the file format promises (ranges, min <= max layers, the maps the technique and
// normal source need), on a material already in memory. Empty when the material is valid.
std::vector<MaterialProblem> validateMaterial(const Material& material,
                                              MaterialCheck check = MaterialCheck::Complete);

// Parses and validates the JSON text; `source` names it in errors. On failure the error lists
// every problem, one a line: "SOURCE: /technique/maxLayers: expected an integer 1..4096, got "x"".
Result<Material> parseMaterial(std::string_view json, const std::string& source,
                               MaterialCheck check = MaterialCheck::Complete);

// Reads, parses and validates a material file. Map paths stay as written (see resolveMapPath).
Result<Material> loadMaterial(const std::string& path,
                              MaterialCheck check = MaterialCheck::Complete);

// The JSON text of a material: every field, current version, keys in a stable order.
std::string materialToJson(const Material& material);

// Validates, then writes atomically; an invalid material is refused with every problem listed.
Status saveMaterial(const Material& material, const std::string& path);

// The file a map path names, for a material stored in `materialFile` ("" when the map is absent).
std::string resolveMapPath(const std::string& materialFile, const std::string& mapPath);

// Records every map `material` names (resolved against `materialFile`) as an input of the run
// (parallax/io/Inputs.h), loaded or not: no output may replace one. loadMaterial does it.
Status noteMaterialMaps(const Material& material, const std::string& materialFile);

// Rewrites relative map paths so they name the same files from a material stored at `toFile`
// instead of `fromFile` (Save As into another folder). Absolute paths are kept.
MaterialMaps rebaseMapPaths(const MaterialMaps& maps, const std::string& fromFile,
                            const std::string& toFile);

// Every problem as "SOURCE: POINTER: message" lines (no trailing newline).
std::string formatProblems(const std::vector<MaterialProblem>& problems, const std::string& source);

} // namespace px

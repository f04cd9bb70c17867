#pragma once
// A material's maps in memory, read through readImage/loadHeightField: what the renderer uploads,
// the bakers read and the exports write.

#include "parallax/Result.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/image/Image.h"
#include "parallax/material/Material.h"

#include <string>

namespace px {

// Which of a material's maps something reads.
struct MapSet {
    bool albedo = false;
    bool height = false;
    bool normal = false;
    bool cone = false;
    bool relaxedCone = false;
    bool ao = false;
    bool roughness = false;
    bool metallic = false;
    bool specular = false;
};

// The maps the material's own shader samples: height for parallax or height-derived normals, the
// normal map for NormalSource::Map, the cone map the technique reads, albedo and AO when there are
// files for them, roughness/metallic under the metallic-roughness model when there are; never the
// specular map, which only engines read. (The
// max-mip pyramid is built when loading, never stored.) A needed cone map the material has no
// file for is still listed: it is baked from the height map.
MapSet mapsUsed(const Material& material);

// Every map the material names a file for.
MapSet mapsPresent(const MaterialMaps& maps);

// Empty members are maps the material does not have (or that were not asked for).
struct MaterialAssets {
    HeightField height;  // channel and invert applied: white = high
    Image albedo;        // as stored: sRGB-encoded values in [0, 1]; 3 or 4 channels
    Image normal;        // as stored, green as Material::normalGreen says; 3+ channels
    ConeMap cone;        // G of the cone map file (R must match the height map)
    ConeMap relaxedCone; // G of the relaxed cone map file
    Image ao;            // linear, as stored
    Image roughness;     // linear, as stored
    Image metallic;      // linear, as stored
    Image specular;      // as stored: grey (a level) or colour
};

struct AssetLoadOptions {
    bool allowLarge = false; // sides over 16384 texels
    bool normalize = false;  // remap the height map's [min, max] to [0, 1]
};

// Loads the maps in `which` that the material has files for, paths resolved against the folder of
// `materialFile` (resolveMapPath). A map in `which` without a file is left empty, except the height
// map, which must be there when asked for. Every failing map is reported, one a line, each naming
// its file: unreadable, not an image, too few channels (normal: 3, cone: 2), a cone map whose size
// or R channel does not match the height map.
Result<MaterialAssets> loadMaterialAssets(const Material& material, const std::string& materialFile,
                                          const MapSet& which,
                                          const AssetLoadOptions& options = {});

} // namespace px

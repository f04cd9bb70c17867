#pragma once
// Exporting a material for the project's own renderer or for an engine.

#include "parallax/Result.h"
#include "parallax/export/ExportFormat.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/Material.h"
#include "parallax/material/MaterialAssets.h"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace px {

struct ExportOptions {
    ExportFormat format = ExportFormat::Package;
    std::string outDir;
    bool force = false; // replace an existing export (see ExportFolder.h)
    // Height: 16-bit PNG (UInt16) or float EXR (Float). Normal maps: 8 or 16-bit PNG.
    PixelFormat heightFormat = PixelFormat::UInt16;
    PixelFormat normalFormat = PixelFormat::UInt8;
    NormalGreen packageGreen = NormalGreen::OpenGL; // the package's normal map convention
    AssetLoadOptions load;
    // Bake an occlusion map from the height map where the material has none (as a missing normal
    // map is baked): the exact bake (parallax/bake/OcclusionBaker.h) at the material's height
    // scale and wrap, default directions, this horizontal uv distance (+inf: unlimited).
    bool bakeOcclusion = false;
    double occlusionDistance = std::numeric_limits<double>::infinity();
    // Where resolving technique "auto" keeps the cone maps it bakes between runs (empty: none).
    std::string coneCacheDir;
};

struct ExportResult {
    std::string folder;
    std::vector<std::string> files; // written, in order (names inside the folder)
    std::vector<std::string> notes; // things the user should know (e.g. a map baked on the way)
    std::vector<std::string> kept;  // files of an earlier export's folder left as they were
};

// Loads the maps the target needs (paths relative to `materialFile`), converts them (bit depth,
// green convention, channel packing, cone maps baked when the material has none, occlusion baked
// when asked), writes them and
// the target's material description into `options.outDir` as one atomic folder. Errors name the
// file or the folder and the problem; on failure nothing is left behind.
Result<ExportResult> exportMaterial(const Material& material, const std::string& materialFile,
                                    const ExportOptions& options);

} // namespace px

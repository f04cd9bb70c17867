#pragma once
// Importing a texture set as a new material: the plan's files loaded, the relief read from the data
// (ReliefReading.h), the normal map put to use, and a summary that lists every file and every
// decision. The editor and `parallax-cli import` both import through here.

#include "parallax/Result.h"
#include "parallax/material/Material.h"
#include "parallax/material/MaterialAssets.h"
#include "parallax/material/ReliefReading.h"
#include "parallax/material/TextureSet.h"

#include <string>
#include <vector>

namespace px {

struct ImportedSet {
    Material material;     // named after the set; map paths absolute
    MaterialAssets assets; // the maps as the material reads them (the height inverted if depth)
    TextureSetPlan plan;
    ReliefReading relief;           // meaningful when the set has a height map
    std::vector<std::string> notes; // what else the import decided
};

// Loads every assigned file of `plan` into a new material with `base`'s settings (scale, technique,
// lighting, ...), named after the set. The height file's reading and the normal map's green come
// from the data when both maps are there (ReliefReading.h); a normal map sets the normal source to
// "map". All or nothing: every file that fails is named in the error, one a line.
Result<ImportedSet> importTextureSet(const TextureSetPlan& plan, const Material& base = {},
                                     const AssetLoadOptions& options = {});

// The summary, one line each: the set, each assigned file and its role, the reading, the notes,
// then every ignored and duplicate file with why.
std::vector<std::string> importSummary(const ImportedSet& set);

} // namespace px

#pragma once
// Importing a texture set as a new material: every file of the plan given its role by its name
// and, where names cannot tell, by its texels (MapContent.h); the relief read from the data
// (ReliefReading.h); packed maps read by channel; and one report that lists every file, the role
// it got and why, or why it was not used. The editor and `parallax-cli import` both import
// through here and show the same report (importSummary).

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/material/Material.h"
#include "parallax/material/MaterialAssets.h"
#include "parallax/material/ReliefReading.h"
#include "parallax/material/TextureSet.h"

#include <string>
#include <vector>

namespace px {

// One file of the set, as the import decided.
struct ImportedFile {
    std::string path;
    std::string role; // "height map", "normal map, height in alpha", "roughness (ORM green)"
    std::string why;  // "tag _disp", "its texels are a normal map", ...; why not, when unused
    bool used = false;
};

struct ImportedSet {
    Material material;     // named after the set; map paths absolute
    MaterialAssets assets; // the maps as the material reads them (the height inverted if depth)
    TextureSetPlan plan;
    ReliefReading relief;            // meaningful when the set has a height map
    std::vector<ImportedFile> files; // every file of the set, in the plan's order
    std::vector<std::string> notes;  // what else the import decided
    // Only a normal map gives the set relief: deriveHeight() can make a height map from it.
    bool heightMissing = false;
};

// Loads the plan's files into a new material with `base`'s settings (scale, technique, ...),
// named after the set. Errors: a file that cannot be read (every one named, one a line); a set
// with neither a height nor a normal map (the message is the report: each file and its role).
Result<ImportedSet> importTextureSet(const TextureSetPlan& plan, const Material& base = {},
                                     const AssetLoadOptions& options = {});

// Makes the missing height map of a normal-only set by integrating its normal map
// (HeightFromNormals.h): the height in memory (no file yet), the height scale from the normal
// map's slopes, the material marked as derived, a note saying so. Errors: the set has a height
// map already, the integration's errors, cancellation.
Status deriveHeight(ImportedSet& set, const BakeControl& control = {});

// The report, one line each: the set, each used file and its role, the relief reading, the notes,
// then every file not used and every file ignored, with why.
std::vector<std::string> importSummary(const ImportedSet& set);

} // namespace px

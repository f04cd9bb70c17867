#pragma once
// Reading maps and materials into a new document state. Every function leaves its input alone and
// returns either the next state or one sentence naming the file and the problem, so a bad file
// changes nothing (the caller only adopts a state that loaded completely).

#include "model/DocumentState.h"
#include "parallax/Result.h"
#include "parallax/material/MapPaths.h"
#include "parallax/material/TextureSetImport.h"

#include <string>
#include <vector>

namespace px::studio {

struct Loaded {
    DocumentState state;
    std::vector<std::string> notes; // what the user should know ("cone maps cleared: ...")
};

// Opens a material file: the material and every map it names, paths made absolute.
Result<Loaded> openMaterialFile(const std::string& path);

// Loads one map into `state`. A height map from a `depth` file is inverted (white = deep). A new
// height map drops cone maps (they describe the old surface) and baked, unsaved normal maps.
// Cone maps must match the height map in size and in their R channel.
Result<Loaded> loadMapFile(const DocumentState& state, MapKind kind, const std::string& path,
                           bool depth = false);

// Reloads the height map from its file with the material's current channel and invert settings
// (after they changed). Fails when the height map has no file.
Result<Loaded> reloadHeight(const DocumentState& state);

// A new document holding an imported texture set: no file yet, the maps the set's files (a height
// map derived from the normal map is held in memory, unsaved, until the material is saved).
DocumentState importedState(ImportedSet set);

} // namespace px::studio

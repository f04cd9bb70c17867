#pragma once
// Reading maps and materials into a new document state. Every function leaves its input alone and
// returns either the next state or one sentence naming the file and the problem, so a bad file
// changes nothing (the caller only adopts a state that loaded completely).

#include "DocumentState.h"
#include "parallax/Result.h"

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

// A map file found by its suffix.
struct FoundMap {
    MapKind kind;
    std::string path;
    bool depth = false;
};

// The image files of a folder (or a list of files) whose suffix names a map, the height map
// first; files with no known suffix are listed in `unmatched`. Errors: unreadable folder.
struct FoundMaps {
    std::vector<FoundMap> maps;
    std::vector<std::string> unmatched;
    std::vector<std::string> duplicates; // a second file for a map already found (skipped)
};
Result<FoundMaps> findMapsInFolder(const std::string& folder);
FoundMaps classifyFiles(const std::vector<std::string>& files);

// Loads every found map into `state`, all or nothing.
Result<Loaded> loadMaps(const DocumentState& state, const std::vector<FoundMap>& maps);

// Map paths relative to / resolved against the folder of `materialFile`.
MaterialMaps absoluteMapPaths(const MaterialMaps& maps, const std::string& materialFile);
MaterialMaps relativeMapPaths(const MaterialMaps& maps, const std::string& materialFile);

} // namespace px::studio

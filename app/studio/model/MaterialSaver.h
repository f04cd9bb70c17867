#pragma once
// Saving a document: maps made in the editor (the sample, bakes) are written beside the material
// as "<name>_<map>.png", then the material JSON with paths relative to its folder. Every file is
// written atomically; on failure the document is left as it was and the error names the file.

#include "model/DocumentState.h"
#include "parallax/Result.h"

#include <string>

namespace px::studio {

// The state as saved: unsaved maps now have files, paths absolute. Maps written: height 16-bit
// PNG, albedo 8-bit sRGB PNG, normal 16-bit PNG, cone maps 16-bit PNG with R = height and
// G = sqrt(ratio) rounded down (docs/conventions.md §4).
Result<DocumentState> saveDocumentState(const DocumentState& state, const std::string& path);

// A state from the undo history after a save: each map it holds unsaved that the save wrote (the
// same data as in `saved`) now has its file, as in `saved`. Undo and redo after a save then never
// mark saved maps unsaved again.
void adoptSavedMaps(DocumentState& state, const DocumentState& saved);

// The file an unsaved map is written to for a material saved at `materialPath`.
std::string mapFileFor(const std::string& materialPath, MapKind kind);

} // namespace px::studio

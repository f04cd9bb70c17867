#pragma once
// Batch export: every texture set in a folder, grouped and read exactly as `import` and the
// editor read one (TextureSet.h, TextureSetImport.h), each made into a material with one preset's
// settings.

#include "parallax/Result.h"
#include "parallax/material/Material.h"
#include "parallax/material/TextureSetImport.h"

#include <string>
#include <vector>

namespace px {

struct BatchItem {
    std::string name;    // the set's name: "Bricks076C" for Bricks076C_1K-PNG_Displacement.png
    TextureSetPlan plan; // its files, as the import groups them
};

struct BatchFolder {
    std::vector<BatchItem> items;        // sorted by name (case-insensitively)
    std::vector<SkippedFile> unassigned; // files of no set, with why
};

// Every texture set in `folder` and the folders in it (one level, as folderFiles reads). Errors:
// the folder is missing or unreadable; no set in it (the message lists every file and why).
Result<BatchFolder> scanBatchFolder(const std::string& folder);

// The item's material: its set imported as `import` does, with `preset`'s settings (its maps are
// not used). Errors: the import's (an unreadable file, a set with no relief), and a set with only
// a normal map (it has no height map to export; `import --derive-height` makes one).
Result<ImportedSet> importBatchItem(const BatchItem& item, const Material& preset,
                                    const AssetLoadOptions& options = {});

} // namespace px

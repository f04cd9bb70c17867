#pragma once
// Which of a folder's files (or of a drop of files) make one texture set, and what each one is
// by its name (MapFileName.h reads the names).
//
// A set is named by the stem its files share: "Bricks076C_1K-PNG_Color.png" and
// "Bricks076C_1K-PNG_NormalGL.png" are the set "Bricks076C". A tag glued to the stem with no
// separator ("stone01z", "stone01n") counts only where a sibling shares that stem, so "stones.png"
// alone is not the specular map of "stone". A file with no tag named after the set ("bricks2.jpg"),
// or after it with a variant letter ("crate1a.jpg" beside "crate1_n.png"), belongs to it: its
// albedo unless its texels say otherwise (TextureSetImport.h). Files named only by a tag
// ("normal.png") belong to the set named after their folder. Every other file is listed with why,
// never silently dropped, and two sets are never mixed.

#include "parallax/Result.h"
#include "parallax/material/MapVocabulary.h"

#include <optional>
#include <string>
#include <vector>

namespace px {

struct SetFile {
    std::string path;
    std::optional<MapRole> role; // by its name; none: named after the set, no tag
    GreenHint green = GreenHint::None;
    std::string why; // "tag _nor_gl_1k", "named after the set", "the set's name and variant a"
};

struct SkippedFile {
    std::string path;
    std::string why; // one phrase: "not an image file", "belongs to the set toy_box", ...
};

struct TextureSetPlan {
    std::string name;                 // the set's name as its files spell it
    std::vector<SetFile> files;       // the set's images, sorted by name
    std::vector<SkippedFile> ignored; // every other file, with why
};

// The names of the sets among `files`, sorted, each once (case-insensitively).
std::vector<std::string> textureSetNames(const std::vector<std::string>& files);

// Plans importing the set named `set` (case-insensitive; empty: the only set there is). `source`
// names the folder or the files in errors. Errors: no set at all (the message lists every file and
// why it is not a map, one a line); several sets and none chosen (the message lists them); `set` is
// none of them.
Result<TextureSetPlan> planTextureSet(const std::vector<std::string>& files,
                                      const std::string& source, const std::string& set = {});

// The files of a folder and of the folders in it (one level, not hidden ones: downloads keep maps
// in textures/ beside a .blend), sorted. Entries that are no regular file (a FIFO, a socket, a
// dangling link, a folder named like an image) are listed too, so that the plan reports them
// (planTextureSet ignores them, saying what they are, and never reads them). Errors: not a
// folder, unreadable.
Result<std::vector<std::string>> folderFiles(const std::string& folder);

} // namespace px

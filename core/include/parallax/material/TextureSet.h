#pragma once
// Which of a folder's files (or of a drop of files) make one texture set, and what each one is.
//
// A set is named by the stem its files share: "bricks2_disp.jpg" and "bricks2_normal.jpg" are the
// set "bricks2" (the role suffixes of docs/conventions.md §6, compared case-insensitively). A file with no
// role suffix whose name is the set's own ("bricks2.jpg") is its albedo. Every other file is
// listed as ignored with the reason, never silently dropped, and two sets are never mixed.

#include "parallax/Result.h"
#include "parallax/material/MapKind.h"

#include <string>
#include <vector>

namespace px {

struct SetFile {
    MapKind kind;
    std::string path;
    bool depthBySuffix = false; // "_depth": white = deep by its name
    std::string why;            // "suffix _disp", "named after the set"
};

struct SkippedFile {
    std::string path;
    std::string why; // one phrase: "not an image", "belongs to the set toy_box", ...
};

struct TextureSetPlan {
    std::string name;                    // the set's name as its files spell it
    std::vector<SetFile> assigned;       // the height map first (cone maps are checked against it)
    std::vector<SkippedFile> ignored;    // not an image, no role suffix, another set's file
    std::vector<SkippedFile> duplicates; // a second file for a role already assigned
    const SetFile* find(MapKind kind) const;
};

// The names of the sets among `files`, sorted, each once (case-insensitively).
std::vector<std::string> textureSetNames(const std::vector<std::string>& files);

// Plans importing the set named `set` (case-insensitive; empty: the only set there is). `source`
// names the folder or the files in errors. Errors: no file with a role suffix; several sets and
// none chosen (the message lists them); `set` is none of them.
Result<TextureSetPlan> planTextureSet(const std::vector<std::string>& files,
                                      const std::string& source, const std::string& set = {});

// The regular files of a folder, sorted. Errors: not a folder, unreadable.
Result<std::vector<std::string>> folderFiles(const std::string& folder);

} // namespace px

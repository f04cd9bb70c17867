#pragma once
// Reading a map file's name as people write it: "Bricks076C_1K-PNG_NormalGL", "rock_nor_gl_2k",
// "stone01z", "T_Wall_ORM", "wall_DISP16_3K". The name is split into words (separators,
// camelCase, letters against digits), words that say nothing of the map are set aside
// (resolution, format, bit depth, level of detail, variant), and the last words are matched
// against the vocabulary (MapVocabulary.h). The words before them are the set's name.

#include "parallax/material/MapVocabulary.h"

#include <string>
#include <string_view>
#include <vector>

namespace px {

struct NameWord {
    std::string text;      // lower case
    std::size_t begin = 0; // in the name as spelled
    std::size_t end = 0;
    bool glued = false; // joined to the word before with no separator or case change ("01z")
};

// The words of a file name's stem (no folder, no extension).
std::vector<NameWord> splitName(std::string_view stem);

struct NameReading {
    std::string stem;            // the set's name as spelled; empty: the name is only a tag
    const MapTag* tag = nullptr; // null: no tag (a file named after its set, or unknown)
    GreenHint green = GreenHint::None;
    bool glued = false;  // the tag is glued to the name ("stone01z"): only siblings confirm it
    std::string tagText; // the tag as spelled, with what follows it: "_nor_gl_1k"
};

// The readings of a file name (path or name; folder and extension are dropped): the one with a
// separated tag first, then a glued one, and last the reading with no tag. Never empty.
std::vector<NameReading> readMapFileName(const std::string& fileName);

} // namespace px

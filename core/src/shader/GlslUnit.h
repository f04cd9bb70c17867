#pragma once
// The little GLSL front end the generator needs: resolve #if on the variant's defines, split a
// file into top-level items (functions, structs, globals, #defines), and keep only the items
// reachable from main(). The shader files are written in the shared subset
// (shaders/trace/README.md), which keeps this simple: no strings, no line continuations.

#include "parallax/Result.h"

#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace px::shader {

// One top-level declaration with the comment lines directly above it.
struct GlslItem {
    std::vector<std::string> names;   // what it declares ("int a, b;": a and b); none for
                                      // directives other than #define
    std::string text;                 // verbatim, comment included, ending with a newline
    int file = 0;                     // source-string number of its file
    int firstLine = 1;                // 1-based line of text's first line in its file
    std::set<std::string> references; // identifiers its code uses (comments excluded)
};

// Evaluates #if / #ifdef / #ifndef / #elif / #else / #endif: every name in `defines` is defined
// (as 1), every other name is not. `defined(X)`, `X`, `!`, `&&`, `||` and parentheses are
// understood. Removed lines become empty, so line numbers do not move. Errors name `path`.
Result<std::string> preprocess(std::string_view text, const std::set<std::string>& defines,
                               const std::string& path);

// Splits preprocessed text into items. Errors (an unbalanced brace, a line continuation) name
// `path` and the line.
Result<std::vector<GlslItem>> splitItems(std::string_view text, int file, const std::string& path);

// The items reachable from `roots` through their references, in their original order. Names
// referenced but declared by no item are added to `external` (uniforms, built-ins).
std::vector<const GlslItem*> reachableItems(const std::vector<GlslItem>& items,
                                            const std::vector<std::string>& roots,
                                            std::set<std::string>& external);
// The same over items held elsewhere (the generator's per-file cache).
std::vector<const GlslItem*> reachableItems(const std::vector<const GlslItem*>& items,
                                            const std::vector<std::string>& roots,
                                            std::set<std::string>& external);

} // namespace px::shader

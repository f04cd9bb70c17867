#pragma once
// Checks, before any work, that a command's outputs can be written and overwrite none of its
// inputs: `bake normal --height x.png --out x.png` must be refused, not answered with exit 0 and
// a lost height map.

#include "parallax/Result.h"

#include <string>
#include <vector>

namespace px {

struct NamedPath {
    std::string option; // "--out", "--height", ...
    std::string path;
};

// Each output must not be a folder, its folder must exist and be writable, and it must not be the
// same file as an input (same device and inode, or the same canonical path) nor as another output.
// Errors name the file, both options and the problem.
Status checkOutputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

// True if both paths name the same existing file, or the same canonical path.
bool sameFile(const std::string& a, const std::string& b);

} // namespace px

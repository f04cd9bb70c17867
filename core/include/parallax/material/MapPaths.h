#pragma once
// A material's map paths made absolute or relative to the folder of the material file that holds
// them. In memory the editor and the import keep them absolute; files hold them relative.

#include "parallax/material/Material.h"

#include <string>

namespace px {

// Map paths resolved against the folder of `materialFile`, made absolute and normal.
MaterialMaps absoluteMapPaths(const MaterialMaps& maps, const std::string& materialFile);

// Map paths relative to the folder of `materialFile` ('/'-separated).
MaterialMaps relativeMapPaths(const MaterialMaps& maps, const std::string& materialFile);

// A path made absolute and normal (kept as it is when the working folder is unknown).
std::string absolutePath(const std::string& path);

} // namespace px

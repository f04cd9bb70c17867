#pragma once
// A file's extension for telling formats apart: artists' folders mix "Rock.PNG" and "rock.png".

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace px {

// ".png" for "maps/Rock.PNG" (ASCII lower case), "" for a name without one.
inline std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

} // namespace px

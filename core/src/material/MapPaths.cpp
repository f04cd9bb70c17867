#include "parallax/material/MapPaths.h"

#include "parallax/material/MapKind.h"
#include "parallax/material/MaterialFile.h"

#include <filesystem>

namespace px {

namespace fs = std::filesystem;

std::string absolutePath(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::absolute(fs::path(path), ec);
    return (ec ? fs::path(path) : p).lexically_normal().string();
}

MaterialMaps absoluteMapPaths(const MaterialMaps& maps, const std::string& materialFile) {
    MaterialMaps out = maps;
    for (MapKind kind : kAllMapKinds) {
        std::string& path = mapPath(out, kind);
        if (!path.empty())
            path = absolutePath(resolveMapPath(absolutePath(materialFile), path));
    }
    return out;
}

MaterialMaps relativeMapPaths(const MaterialMaps& maps, const std::string& materialFile) {
    MaterialMaps out = maps;
    const fs::path dir = fs::path(absolutePath(materialFile)).parent_path();
    for (MapKind kind : kAllMapKinds) {
        std::string& path = mapPath(out, kind);
        if (path.empty())
            continue;
        const fs::path relative = fs::path(absolutePath(path)).lexically_relative(dir);
        if (!relative.empty())
            path = relative.generic_string();
    }
    return out;
}

} // namespace px

// Loading and saving material files, and the paths of their maps.

#include "parallax/material/MaterialFile.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"
#include "parallax/material/MapKind.h"

#include <filesystem>

namespace px {

namespace fs = std::filesystem;

namespace {

// A material file is a few hundred bytes; anything far larger is not one.
constexpr std::uintmax_t kMaxMaterialFileBytes = 1 << 20;

} // namespace

Result<Material> loadMaterial(const std::string& path, MaterialCheck check) {
    std::error_code ec;
    if (const std::uintmax_t size = fs::file_size(path, ec); !ec && size > kMaxMaterialFileBytes)
        return fileError(path, "the file is " + std::to_string(size) +
                                   " bytes, too large for a material file (limit 1 MiB)");
    Result<std::string> text = readTextFile(path);
    if (!text)
        return text.error();
    Result<Material> material = parseMaterial(*text, path, check);
    if (!material)
        return material;
    if (Status s = noteMaterialMaps(*material, path); !s)
        return s.error();
    return material;
}

Status saveMaterial(const Material& material, const std::string& path) {
    if (std::vector<MaterialProblem> problems = validateMaterial(material); !problems.empty())
        return Error{formatProblems(problems, path)};
    return writeTextFile(path, materialToJson(material));
}

Status noteMaterialMaps(const Material& material, const std::string& materialFile) {
    const MaterialMaps& maps = material.maps;
    const std::pair<const std::string*, const char*> named[] = {{&maps.albedo, "albedo"},
                                                                {&maps.height, "height"},
                                                                {&maps.normal, "normal"},
                                                                {&maps.cone, "cone"},
                                                                {&maps.relaxedCone, "relaxed cone"},
                                                                {&maps.ao, "AO"},
                                                                {&maps.roughness, "roughness"},
                                                                {&maps.metallic, "metallic"}};
    const std::string owner = materialFile.empty() ? material.name : materialFile;
    for (const auto& [map, what] : named) {
        const std::string role = std::string("the ") + what + " map of " + owner;
        if (Status s = noteInput(resolveMapPath(materialFile, *map), role); !s)
            return s;
    }
    return success();
}

std::string resolveMapPath(const std::string& materialFile, const std::string& mapPath) {
    if (mapPath.empty())
        return {};
    const fs::path map(mapPath);
    if (map.is_absolute())
        return map.lexically_normal().string();
    return (fs::path(materialFile).parent_path() / map).lexically_normal().string();
}

MaterialMaps rebaseMapPaths(const MaterialMaps& maps, const std::string& fromFile,
                            const std::string& toFile) {
    std::error_code ec;
    const fs::path toDir = fs::weakly_canonical(fs::absolute(toFile, ec).parent_path(), ec);
    auto rebase = [&](const std::string& path) -> std::string {
        if (path.empty() || fs::path(path).is_absolute())
            return path;
        std::error_code e;
        const fs::path file =
            fs::weakly_canonical(fs::absolute(resolveMapPath(fromFile, path), e), e);
        const fs::path relative = file.lexically_relative(toDir);
        return relative.empty() ? file.generic_string() : relative.generic_string();
    };
    MaterialMaps out;
    for (MapKind kind : kAllMapKinds)
        mapPath(out, kind) = rebase(mapPath(maps, kind));
    return out;
}

} // namespace px

#include "parallax/material/TextureSetImport.h"

#include "parallax/material/MapPaths.h"

#include <filesystem>

namespace px {

namespace {

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

std::string lowerTitle(MapKind kind) {
    std::string title(mapTitle(kind));
    if (!title.empty())
        title[0] = static_cast<char>(title[0] - 'A' + 'a');
    return title;
}

void invert(HeightField& field) {
    for (float& h : field.texels)
        h = 1.0f - h;
}

} // namespace

Result<ImportedSet> importTextureSet(const TextureSetPlan& plan, const Material& base,
                                     const AssetLoadOptions& options) {
    const SetFile* height = plan.find(MapKind::Height);
    const SetFile* normal = plan.find(MapKind::Normal);
    if (!height)
        return Error{"The texture set " + plan.name +
                     " has no height map (a file ending in _height, _disp, _displacement or "
                     "_depth)."};
    ImportedSet out;
    out.plan = plan;
    Material& m = out.material;
    m = base;
    m.name = plan.name;
    m.maps = {};
    for (const SetFile& file : plan.assigned)
        mapPath(m.maps, file.kind) = absolutePath(file.path);
    m.heightIsDepth = height->depthBySuffix;
    out.relief = reliefByName(m.heightIsDepth, height->path);

    // The height file as stored and the normal map first: they decide how the height reads.
    MaterialAssets first;
    if (normal) {
        Material raw = m;
        raw.heightIsDepth = false;
        MapSet pair;
        pair.height = pair.normal = true;
        Result<MaterialAssets> loaded = loadMaterialAssets(raw, m.maps.height, pair, options);
        if (!loaded)
            return loaded.error();
        first = std::move(*loaded);
        Result<ReliefReading> reading =
            readRelief(first.height, first.normal, m.wrap, m.heightIsDepth, normal->path);
        if (!reading)
            return reading.error();
        out.relief = std::move(*reading);
        m.heightIsDepth = out.relief.depth;
        if (out.relief.fromData)
            m.normalGreen = out.relief.green;
        if (m.heightIsDepth)
            invert(first.height);
        m.normalSource = NormalSource::Map;
        out.notes.push_back("The normal map shades the surface (Normals: map).");
    } else if (m.normalSource == NormalSource::Map) {
        m.normalSource = NormalSource::HeightCentral;
    }

    // The rest; cone maps are checked against the height map, so they need it loaded with them.
    MapSet rest = mapsPresent(m.maps);
    if (normal && !rest.cone && !rest.relaxedCone)
        rest.height = rest.normal = false;
    Result<MaterialAssets> loaded = loadMaterialAssets(m, m.maps.height, rest, options);
    if (!loaded)
        return loaded.error();
    out.assets = std::move(*loaded);
    if (!rest.height) {
        out.assets.height = std::move(first.height);
        out.assets.normal = std::move(first.normal);
    }
    return out;
}

std::vector<std::string> importSummary(const ImportedSet& set) {
    std::vector<std::string> lines;
    lines.push_back("Texture set " + set.plan.name + " imported as the material " +
                    set.material.name + ":");
    for (const SetFile& file : set.plan.assigned) {
        std::string line =
            "  " + lowerTitle(file.kind) + " map: " + fileName(file.path) + " (" + file.why + ")";
        if (file.kind == MapKind::Height)
            line += set.material.heightIsDepth ? ", read as depth (white = deep)"
                                               : ", read as height (white = high)";
        if (file.kind == MapKind::Normal)
            line += set.material.normalGreen == NormalGreen::OpenGL ? ", green OpenGL (Y+)"
                                                                    : ", green DirectX (Y-)";
        lines.push_back(line);
    }
    lines.push_back(set.relief.summary);
    lines.insert(lines.end(), set.notes.begin(), set.notes.end());
    for (const SkippedFile& file : set.plan.duplicates)
        lines.push_back("Duplicate, not used: " + fileName(file.path) + " (" + file.why + ")");
    for (const SkippedFile& file : set.plan.ignored)
        lines.push_back("Ignored: " + fileName(file.path) + " (" + file.why + ")");
    return lines;
}

} // namespace px

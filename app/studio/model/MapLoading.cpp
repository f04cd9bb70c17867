#include "model/MapLoading.h"

#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/MapPaths.h"
#include "parallax/material/MaterialFile.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string_view>

namespace px::studio {

namespace {

Result<Image> readMapImage(const std::string& path, int minChannels, const char* what) {
    Result<Image> image = readImage(
        path, std::string_view(what) == "colour map" ? colourMapReading() : ImageReadOptions{});
    if (!image)
        return image.error();
    if (image->channels < minChannels)
        return fileError(path, std::string("a ") + what + " needs at least " +
                                   std::to_string(minChannels) + " channels, the file has " +
                                   std::to_string(image->channels));
    return image;
}

// Grey colour maps become RGB, so the renderer sees one layout.
Image toRgb(Image image) {
    if (image.channels >= 3)
        return image;
    Image rgb(image.width, image.height, 3);
    const ImageWriter put = rgb.writer();
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                put.at(x, y, c) = image.at(x, y, 0);
    return rgb;
}

// A cone map file: R the height it was baked from (must be this height map's), G sqrt(ratio).
Result<ConeMap> readConeMap(const std::string& path, ConeKind kind, const HeightField& height) {
    if (height.empty())
        return fileError(path, "load a height map before its cone map");
    Result<Image> image = readMapImage(path, 2, "cone map");
    if (!image)
        return image.error();
    if (image->width != height.width || image->height != height.height)
        return fileError(path, "the cone map is " + std::to_string(image->width) + "x" +
                                   std::to_string(image->height) + " but the height map is " +
                                   std::to_string(height.width) + "x" +
                                   std::to_string(height.height));
    ConeMap cone(kind, image->width, image->height);
    float worst = 0.0f;
    for (int y = 0; y < image->height; ++y) {
        for (int x = 0; x < image->width; ++x) {
            const float g = image->at(x, y, 1);
            if (!(g >= 0.0f && g <= 1.0f))
                return fileError(path, "cone value outside [0, 1] at texel (" + std::to_string(x) +
                                           ", " + std::to_string(y) + ")");
            cone.g(x, y) = g;
            worst = std::max(worst, std::abs(image->at(x, y, 0) - height.at(x, y)));
        }
    }
    // An 8-bit file holds the height to half a step; more means another height map.
    if (worst > 1.0f / 255.0f) {
        std::ostringstream text;
        text << "the cone map's height (R) differs from the height map by up to " << worst
             << ": it was baked from another height map; bake it again";
        return fileError(path, text.str());
    }
    return cone;
}

void clearMap(MaterialAssets& assets, DocumentState& state, MapKind kind) {
    switch (kind) {
    case MapKind::Cone:
        assets.cone = {};
        break;
    case MapKind::RelaxedCone:
        assets.relaxedCone = {};
        break;
    case MapKind::Normal:
        assets.normal = {};
        state.normalBake.reset();
        break;
    case MapKind::Ao:
        assets.ao = {};
        state.occlusionBake.reset();
        break;
    default:
        break;
    }
    mapPath(state.material.maps, kind).clear();
    state.setUnsaved(kind, false);
}

// A new height map: cone maps and baked normal maps describe the old surface.
void dropDerivedMaps(DocumentState& state, MaterialAssets& assets,
                     std::vector<std::string>& notes) {
    if (state.hasMap(MapKind::Cone) || state.hasMap(MapKind::RelaxedCone)) {
        clearMap(assets, state, MapKind::Cone);
        clearMap(assets, state, MapKind::RelaxedCone);
        notes.push_back("Cone maps cleared: they were baked from the previous height map.");
    }
    if (state.isUnsaved(MapKind::Normal)) {
        clearMap(assets, state, MapKind::Normal);
        if (state.material.normalSource == NormalSource::Map)
            state.material.normalSource = NormalSource::HeightCentral;
        notes.push_back("Baked normal map cleared: it was baked from the previous height map.");
    }
}

} // namespace

Result<Loaded> openMaterialFile(const std::string& path) {
    Result<Material> material = loadMaterial(path);
    if (!material)
        return material.error();
    MapSet which = mapsPresent(material->maps);
    Result<MaterialAssets> assets = loadMaterialAssets(*material, path, which);
    if (!assets)
        return assets.error();
    Loaded loaded;
    loaded.state.material = std::move(*material);
    loaded.state.material.maps = absoluteMapPaths(loaded.state.material.maps, path);
    MaterialAssets maps = std::move(*assets);
    maps.albedo = maps.albedo.empty() ? Image{} : toRgb(std::move(maps.albedo));
    loaded.state.assets = std::make_shared<const MaterialAssets>(std::move(maps));
    return loaded;
}

Result<Loaded> loadMapFile(const DocumentState& state, MapKind kind, const std::string& path,
                           bool depth) {
    Loaded loaded;
    loaded.state = state;
    DocumentState& next = loaded.state;
    MaterialAssets assets = *state.assets;
    switch (kind) {
    case MapKind::Height: {
        HeightLoadOptions options;
        options.channel = state.material.heightChannel;
        options.invert = depth;
        // The same file read again keeps the range the material has for it, where it still fits.
        if (!state.material.maps.height.empty() &&
            absolutePath(path) == absolutePath(state.material.maps.height))
            options.range = state.material.heightRange;
        Result<FittedHeight> fitted = loadHeightFieldFitted(path, options);
        if (!fitted)
            return fitted.error();
        assets.height = std::move(fitted->field);
        next.material.heightRange = fitted->range;
        if (fitted->range && fitted->range != state.material.heightRange) {
            std::ostringstream note;
            note << std::filesystem::path(path).filename().string() << " holds heights from "
                 << fitted->range->lo << " to " << fitted->range->hi
                 << " (a float map in its own units): read as stored, that range as 0 to 1; "
                    "the material records it.";
            loaded.notes.push_back(note.str());
        }
        next.material.heightIsDepth = depth;
        next.material.heightDerivedFrom.clear();
        dropDerivedMaps(next, assets, loaded.notes);
        break;
    }
    case MapKind::Albedo: {
        Result<Image> image = readMapImage(path, 1, "colour map");
        if (!image)
            return image.error();
        assets.albedo = toRgb(std::move(*image));
        break;
    }
    case MapKind::Normal: {
        Result<Image> image = readMapImage(path, 3, "normal map");
        if (!image)
            return image.error();
        assets.normal = std::move(*image);
        next.normalBake.reset();
        // A normal map is loaded to be used (unless the user turned normals off).
        if (next.material.normalSource != NormalSource::None &&
            next.material.normalSource != NormalSource::Map) {
            next.material.normalSource = NormalSource::Map;
            loaded.notes.push_back("Normals: map (the loaded normal map shades the surface).");
        }
        break;
    }
    case MapKind::Cone:
    case MapKind::RelaxedCone: {
        const ConeKind coneKind =
            kind == MapKind::Cone ? ConeKind::Conservative : ConeKind::Relaxed;
        Result<ConeMap> cone = readConeMap(path, coneKind, state.assets->height);
        if (!cone)
            return cone.error();
        (kind == MapKind::Cone ? assets.cone : assets.relaxedCone) = std::move(*cone);
        break;
    }
    case MapKind::Specular: {
        Result<Image> image = readMapImage(path, 1, "specular map");
        if (!image)
            return image.error();
        assets.specular = std::move(*image);
        loaded.notes.push_back("The specular map is kept for the exports that read one (glTF, "
                               "Unreal); the preview does not draw it.");
        break;
    }
    case MapKind::Ao:
    case MapKind::Roughness:
    case MapKind::Metallic: {
        Result<Image> image = readMapImage(path, 1, "map");
        if (!image)
            return image.error();
        Image& slot = kind == MapKind::Ao          ? assets.ao
                      : kind == MapKind::Roughness ? assets.roughness
                                                   : assets.metallic;
        slot = std::move(*image);
        // A file of its own: read as stored, not as the packed file it replaces.
        (kind == MapKind::Ao          ? next.material.surface.ao
         : kind == MapKind::Roughness ? next.material.surface.roughness
                                      : next.material.surface.metallic) = HeightChannel::Red;
        if (kind == MapKind::Roughness)
            next.material.surface.gloss = false;
        if (kind == MapKind::Ao)
            next.occlusionBake.reset();
        break;
    }
    }
    mapPath(next.material.maps, kind) = absolutePath(path);
    next.setUnsaved(kind, false);
    next.assets = std::make_shared<const MaterialAssets>(std::move(assets));
    return loaded;
}

Result<Loaded> reloadHeight(const DocumentState& state) {
    const std::string& file = state.material.maps.height;
    if (file.empty() || state.isUnsaved(MapKind::Height))
        return Error{"The height map was made here and has no file to read again."};
    return loadMapFile(state, MapKind::Height, file, state.material.heightIsDepth);
}

DocumentState importedState(ImportedSet set) {
    DocumentState state;
    state.material = std::move(set.material);
    set.assets.albedo = set.assets.albedo.empty() ? Image{} : toRgb(std::move(set.assets.albedo));
    // A height map derived from the normal map has no file yet: saved with the material.
    state.setUnsaved(MapKind::Height,
                     !set.assets.height.empty() && state.material.maps.height.empty());
    state.assets = std::make_shared<const MaterialAssets>(std::move(set.assets));
    return state;
}

} // namespace px::studio

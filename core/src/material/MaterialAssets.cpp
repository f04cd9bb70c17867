#include "parallax/material/MaterialAssets.h"

#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/MaterialFile.h"

#include <cmath>
#include <sstream>
#include <string_view>

namespace px {

MapSet mapsPresent(const MaterialMaps& maps) {
    MapSet set;
    set.albedo = !maps.albedo.empty();
    set.height = !maps.height.empty();
    set.normal = !maps.normal.empty();
    set.cone = !maps.cone.empty();
    set.relaxedCone = !maps.relaxedCone.empty();
    set.ao = !maps.ao.empty();
    set.roughness = !maps.roughness.empty();
    set.metallic = !maps.metallic.empty();
    set.specular = !maps.specular.empty();
    return set;
}

MapSet mapsUsed(const Material& m) {
    const TechniqueInfo& technique = info(m.technique);
    const MapSet present = mapsPresent(m.maps);
    MapSet set;
    set.albedo = present.albedo;
    set.height = technique.parallax || m.normalSource == NormalSource::HeightCentral ||
                 m.normalSource == NormalSource::HeightSobel;
    set.normal = m.normalSource == NormalSource::Map;
    set.cone = technique.needsConeMap;
    set.relaxedCone = technique.needsRelaxedConeMap;
    // Occlusion darkens either lighting model; roughness and metallic are metallic-roughness only.
    const bool pbr = m.lighting == LightingModel::MetallicRoughness;
    set.ao = present.ao;
    set.roughness = pbr && present.roughness;
    set.metallic = pbr && present.metallic;
    return set;
}

namespace {

// Collects one line per failing map.
struct Problems {
    std::string text;
    void add(const std::string& message) { text += (text.empty() ? "" : "\n") + message; }
};

Image loadImage(const std::string& file, int minChannels, const char* what,
                const AssetLoadOptions& options, Problems& problems) {
    ImageReadOptions read =
        std::string_view(what) == "colour map" ? colourMapReading() : ImageReadOptions{};
    read.maxSide = options.allowLarge ? (1 << 30) : 16384;
    Result<Image> image = readImage(file, read);
    if (!image) {
        problems.add(image.error().message);
        return {};
    }
    if (image->channels < minChannels) {
        problems.add(fileError(file, std::string("a ") + what + " needs at least " +
                                         std::to_string(minChannels) + " channels, the file has " +
                                         std::to_string(image->channels))
                         .message);
        return {};
    }
    return std::move(*image);
}

// An occlusion, roughness or metallic map: as stored, or the one channel a packed file holds it
// in (inverted for gloss), so everything downstream reads channel 0 as before.
Image loadSurface(const std::string& file, HeightChannel channel, bool invert, const char* what,
                  const AssetLoadOptions& options, Problems& problems) {
    Image image = loadImage(file, 1, what, options, problems);
    if (image.empty() || (channel == HeightChannel::Red && !invert))
        return image;
    HeightLoadOptions pick;
    pick.channel = channel;
    pick.invert = invert;
    Result<HeightField> one = heightFieldFromImage(std::move(image), pick, file);
    if (!one) {
        problems.add(one.error().message);
        return {};
    }
    return one->toImage();
}

// A cone map file: R = height (checked against the height map), G = sqrt(cone ratio).
ConeMap loadCone(const std::string& file, ConeKind kind, const HeightField& height,
                 const AssetLoadOptions& options, Problems& problems) {
    const Image image = loadImage(file, 2, "cone map", options, problems);
    if (image.empty())
        return {};
    if (!height.empty() && (image.width != height.width || image.height != height.height)) {
        problems.add(fileError(file, "the cone map is " + std::to_string(image.width) + "x" +
                                         std::to_string(image.height) + " but the height map is " +
                                         std::to_string(height.width) + "x" +
                                         std::to_string(height.height))
                         .message);
        return {};
    }
    ConeMap cone(kind, image.width, image.height);
    float worst = 0.0f;
    int worstX = 0, worstY = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float g = image.at(x, y, 1);
            if (g < 0.0f || g > 1.0f) {
                problems.add(fileError(file, "cone value outside [0, 1] at texel (" +
                                                 std::to_string(x) + ", " + std::to_string(y) + ")")
                                 .message);
                return {};
            }
            cone.g(x, y) = g;
            if (!height.empty()) {
                const float d = std::abs(image.at(x, y, 0) - height.at(x, y));
                if (d > worst) {
                    worst = d;
                    worstX = x;
                    worstY = y;
                }
            }
        }
    }
    // R is the height the cones were baked from; an 8-bit file holds it to half a step.
    if (worst > 1.0f / 255.0f) {
        std::ostringstream text;
        text << "the cone map's height (R) differs from the height map by up to " << worst
             << " (at texel (" << worstX << ", " << worstY
             << ")): it was baked from another height map; bake it again";
        problems.add(fileError(file, text.str()).message);
        return {};
    }
    return cone;
}

} // namespace

Result<MaterialAssets> loadMaterialAssets(const Material& m, const std::string& materialFile,
                                          const MapSet& which, const AssetLoadOptions& options) {
    MaterialAssets assets;
    Problems problems;
    auto file = [&](const std::string& path) { return resolveMapPath(materialFile, path); };

    if (which.height) {
        if (m.maps.height.empty()) {
            problems.add(fileError(materialFile, "the material has no height map").message);
        } else {
            HeightLoadOptions load;
            load.channel = m.heightChannel;
            load.invert = m.heightIsDepth;
            load.allowLarge = options.allowLarge;
            load.normalize = options.normalize;
            load.range = m.heightRange;
            Result<HeightField> field = loadHeightField(file(m.maps.height), load);
            if (field)
                assets.height = std::move(*field);
            else
                problems.add(field.error().message);
        }
    }
    if (which.albedo && !m.maps.albedo.empty())
        assets.albedo = loadImage(file(m.maps.albedo), 1, "colour map", options, problems);
    if (which.normal && !m.maps.normal.empty())
        assets.normal = loadImage(file(m.maps.normal), 3, "normal map", options, problems);
    if (which.cone && !m.maps.cone.empty())
        assets.cone =
            loadCone(file(m.maps.cone), ConeKind::Conservative, assets.height, options, problems);
    if (which.relaxedCone && !m.maps.relaxedCone.empty())
        assets.relaxedCone =
            loadCone(file(m.maps.relaxedCone), ConeKind::Relaxed, assets.height, options, problems);
    if (which.ao && !m.maps.ao.empty())
        assets.ao = loadSurface(file(m.maps.ao), m.surface.ao, false, "AO map", options, problems);
    if (which.roughness && !m.maps.roughness.empty())
        assets.roughness = loadSurface(file(m.maps.roughness), m.surface.roughness, m.surface.gloss,
                                       "roughness map", options, problems);
    if (which.metallic && !m.maps.metallic.empty())
        assets.metallic = loadSurface(file(m.maps.metallic), m.surface.metallic, false,
                                      "metallic map", options, problems);
    if (which.specular && !m.maps.specular.empty())
        assets.specular = loadImage(file(m.maps.specular), 1, "specular map", options, problems);

    if (!problems.text.empty())
        return Error{problems.text};
    return assets;
}

} // namespace px

#include "model/MaterialSaver.h"

#include "model/MapLoading.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"
#include "parallax/io/OutputGate.h"
#include "parallax/material/MaterialFile.h"

#include <cmath>
#include <filesystem>

namespace px::studio {

namespace fs = std::filesystem;

namespace {

// R = height, G = sqrt(ratio) rounded down to 16 bits so a stored cone is never wider.
Image coneFileImage(const HeightField& height, const ConeMap& cone) {
    Image image(cone.width, cone.height, 3);
    const ImageWriter put = image.writer();
    for (int y = 0; y < cone.height; ++y) {
        for (int x = 0; x < cone.width; ++x) {
            put.at(x, y, 0) = height.at(x, y);
            put.at(x, y, 1) = std::floor(cone.g(x, y) * 65535.0f) / 65535.0f;
        }
    }
    return image;
}

Status writeMap(const MaterialAssets& assets, MapKind kind, const std::string& file) {
    ImageWriteOptions options;
    options.format = PixelFormat::UInt16;
    switch (kind) {
    case MapKind::Height:
        return writeImage(file, assets.height.toImage(), options);
    case MapKind::Normal:
        return writeImage(file, assets.normal, options);
    case MapKind::Cone:
        return writeImage(file, coneFileImage(assets.height, assets.cone), options);
    case MapKind::RelaxedCone:
        return writeImage(file, coneFileImage(assets.height, assets.relaxedCone), options);
    case MapKind::Albedo:
        options.format = PixelFormat::UInt8;
        options.srgb = true;
        return writeImage(file, assets.albedo, options);
    case MapKind::Ao:
        options.format = PixelFormat::UInt8;
        return writeImage(file, assets.ao, options);
    case MapKind::Roughness:
        options.format = PixelFormat::UInt8;
        return writeImage(file, assets.roughness, options);
    case MapKind::Metallic:
        options.format = PixelFormat::UInt8;
        return writeImage(file, assets.metallic, options);
    case MapKind::Specular:
        options.format = PixelFormat::UInt8;
        return writeImage(file, assets.specular, options);
    }
    return success();
}

// Same pixels: shared memory, or equal texel for texel.
bool sameData(const SharedTexels<float>& a, const SharedTexels<float>& b) {
    return a == b;
}

bool sameMap(const MaterialAssets& a, const MaterialAssets& b, MapKind kind) {
    switch (kind) {
    case MapKind::Height:
        return a.height.width == b.height.width && sameData(a.height.texels, b.height.texels);
    case MapKind::Albedo:
        return a.albedo.width == b.albedo.width && sameData(a.albedo.pixels, b.albedo.pixels);
    case MapKind::Normal:
        return a.normal.width == b.normal.width && sameData(a.normal.pixels, b.normal.pixels);
    case MapKind::Cone:
        return a.cone.width == b.cone.width && sameData(a.cone.sqrtRatio, b.cone.sqrtRatio);
    case MapKind::RelaxedCone:
        return a.relaxedCone.width == b.relaxedCone.width &&
               sameData(a.relaxedCone.sqrtRatio, b.relaxedCone.sqrtRatio);
    case MapKind::Ao:
        return a.ao.width == b.ao.width && sameData(a.ao.pixels, b.ao.pixels);
    case MapKind::Roughness:
        return a.roughness.width == b.roughness.width &&
               sameData(a.roughness.pixels, b.roughness.pixels);
    case MapKind::Metallic:
        return a.metallic.width == b.metallic.width &&
               sameData(a.metallic.pixels, b.metallic.pixels);
    case MapKind::Specular:
        return a.specular.width == b.specular.width &&
               sameData(a.specular.pixels, b.specular.pixels);
    }
    return false;
}

} // namespace

void adoptSavedMaps(DocumentState& state, const DocumentState& saved) {
    // The light a material is saved with is the view's, not an undo step: every step has the
    // saved one, so undoing to the saved state is clean again.
    state.material.light = saved.material.light;
    for (MapKind kind : kAllMapKinds) {
        if (!state.isUnsaved(kind) || saved.isUnsaved(kind) || !saved.hasMap(kind) ||
            mapPath(saved.material.maps, kind).empty() ||
            !sameMap(*state.assets, *saved.assets, kind))
            continue;
        mapPath(state.material.maps, kind) = mapPath(saved.material.maps, kind);
        state.setUnsaved(kind, false);
        if (kind == MapKind::Height) {
            state.material.heightIsDepth = saved.material.heightIsDepth;
            state.material.heightChannel = saved.material.heightChannel;
            state.material.heightRange = saved.material.heightRange;
        }
    }
}

std::string mapFileFor(const std::string& materialPath, MapKind kind) {
    const fs::path material(materialPath);
    std::string key(mapKey(kind));
    for (char& c : key)
        c = c == '-' ? '_' : c;
    return (material.parent_path() / (material.stem().string() + "_" + key + ".png")).string();
}

Result<DocumentState> saveDocumentState(const DocumentState& state, const std::string& path) {
    // The map files the document reads as they are are inputs (parallax/io/Inputs.h): neither the
    // material file ("Save As bricks_height.png") nor a map written on the way may replace one.
    const InputSession session;
    for (MapKind kind : kAllMapKinds) {
        const std::string& file = mapPath(state.material.maps, kind);
        if (!state.isUnsaved(kind) && !file.empty()) {
            if (Status s = noteInput(file, "a map of the material"); !s)
                return s.error();
        }
    }
    // Every file the save writes is checked before the first is written: a refusal leaves none.
    if (Result<fs::path> target = outputTarget(path); !target)
        return target.error();
    for (MapKind kind : kAllMapKinds) {
        if (state.isUnsaved(kind) && state.hasMap(kind)) {
            if (Result<fs::path> target = outputTarget(mapFileFor(path, kind)); !target)
                return target.error();
        }
    }
    DocumentState saved = state;
    OutputBatch outputs; // the maps and the material file, all or none (AtomicWrite.h)
    for (MapKind kind : kAllMapKinds) {
        if (!state.isUnsaved(kind) || !state.hasMap(kind))
            continue;
        const std::string file = mapFileFor(path, kind);
        if (Status written = writeMap(*state.assets, kind, file); !written)
            return written.error();
        mapPath(saved.material.maps, kind) = fs::absolute(file).lexically_normal().string();
        saved.setUnsaved(kind, false);
        if (kind == MapKind::Height) {
            // The file holds heights as they are in memory: white = high, in red.
            saved.material.heightIsDepth = false;
            saved.material.heightChannel = HeightChannel::Red;
            saved.material.heightRange.reset(); // ... from 0 to 1
        }
    }
    Material onDisk = saved.material;
    onDisk.maps = relativeMapPaths(saved.material.maps, path);
    if (Status written = saveMaterial(onDisk, path); !written)
        return written.error();
    if (Status committed = outputs.commit(); !committed)
        return committed.error();
    return saved;
}

} // namespace px::studio

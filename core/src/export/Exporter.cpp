// exportMaterial: load what the target needs, write it through the target's writer into a
// staging folder, swap the folder into place.

#include "parallax/export/Exporter.h"

#include "ExportJob.h"
#include "ExportTextures.h"
#include "io/ShortestDecimal.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/NormalMapBaker.h"
#include "parallax/bake/OcclusionBaker.h"
#include "parallax/eval/AutoTechnique.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"
#include "parallax/material/MaterialFile.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace px {

namespace exporter {

namespace {

// The code point of the UTF-8 sequence at `at` and its length, or length 0 if it is not one
// (overlong, a surrogate, past U+10FFFF, cut short).
std::pair<char32_t, std::size_t> codePoint(const std::string& text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
    if (length == 0 || lead > 0xF4 || at + length > text.size())
        return {0, 0};
    char32_t c = lead & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(at + k) & 0xC0) != 0x80)
            return {0, 0};
        c = (c << 6) | (byte(at + k) & 0x3F);
    }
    const char32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
    if (c < least[length] || (c >= 0xD800 && c <= 0xDFFF) || c > 0x10FFFF)
        return {0, 0};
    return {c, length};
}

// Characters a file name should not hold although the file system takes them: C1 controls,
// invisible spaces and joiners, the byte-order mark, and bidirectional overrides (a name that
// reads differently from what it is).
bool invisible(char32_t c) {
    return c < 0xA0 || c == 0xAD || (c >= 0x200B && c <= 0x200F) || (c >= 0x2028 && c <= 0x202E) ||
           (c >= 0x2060 && c <= 0x206F) || c == 0xFEFF;
}

} // namespace

std::string fileStem(const std::string& name) {
    constexpr std::size_t kMaxBytes = 100; // names under the file systems' 255 with suffixes
    std::string stem;
    for (std::size_t at = 0; at < name.size();) {
        const char c = name[at];
        std::string piece = "_";
        std::size_t used = 1;
        if (static_cast<unsigned char>(c) < 0x80) {
            const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                              (c >= '0' && c <= '9') || c == '-' || c == '_';
            if (keep)
                piece = std::string(1, c);
        } else if (const auto [point, length] = codePoint(name, at); length > 0) {
            used = length;
            if (!invisible(point))
                piece = name.substr(at, length);
        }
        if (stem.size() + piece.size() > kMaxBytes)
            break;
        stem += piece;
        at += used;
    }
    return stem.empty() ? "material" : stem;
}

std::string formatDecimal(float value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", shortestDecimal(value));
    return buffer;
}

Status ExportJob::image(const std::string& name, const Image& pixels, PixelFormat format,
                        bool srgb) {
    ImageWriteOptions write;
    write.format = format;
    write.srgb = srgb;
    const std::string staged = folder.pathFor(name);
    if (Status s = writeImage(staged, pixels, write); !s)
        return folder.asTarget(s.error());
    folder.add(name);
    return success();
}

Status ExportJob::text(const std::string& name, std::string_view contents) {
    if (Status s = writeTextFile(folder.pathFor(name), contents); !s)
        return folder.asTarget(s.error());
    folder.add(name);
    return success();
}

std::string ExportJob::heightName(const std::string& base) const {
    return base +
           (options.heightFormat == PixelFormat::Float || options.heightFormat == PixelFormat::Half
                ? ".exr"
                : ".png");
}

Result<Image> ExportJob::normals(NormalGreen green) {
    if (!assets.normal.empty())
        return convertNormalMap(assets.normal, material.normalGreen, green,
                                resolveMapPath(materialFile, material.maps.normal));
    if (assets.height.empty()) {
        result.notes.push_back("no normal map: the material has neither a normal map nor a "
                               "height map to bake one from");
        return Image{};
    }
    NormalBakeOptions bake;
    bake.heightScale = material.heightScale;
    bake.filter = material.normalSource == NormalSource::HeightCentral ? NormalFilter::Central
                                                                       : NormalFilter::Sobel;
    bake.wrap = material.wrap;
    bake.green = green;
    result.notes.push_back("normal map baked from the height map (" +
                           std::string(toString(bake.filter)) + ", height scale " +
                           formatDecimal(material.heightScale) + ", " +
                           (green == NormalGreen::OpenGL ? "OpenGL Y+" : "DirectX Y-") + ")");
    return bakeNormalMap(assets.height, bake);
}

Result<bool> ExportJob::writeNormals(const std::string& name, NormalGreen green) {
    Result<Image> map = normals(green);
    if (!map)
        return map.error();
    if (map->empty())
        return false;
    if (Status s = image(name, *map, options.normalFormat); !s)
        return s.error();
    return true;
}

std::optional<Image> ExportJob::orm(MissingChannel missing) const {
    const bool one = missing == MissingChannel::One;
    const ChannelSource sources[3] = {
        {&assets.ao, 0, false, 1.0f},
        {&assets.roughness, 0, false, one ? 1.0f : material.roughness},
        {&assets.metallic, 0, false, one ? 1.0f : material.metallic}};
    return packChannels(sources, 3, material.wrap);
}

void ExportJob::noteOcclusion(const std::string& where) {
    if (assets.ao.empty())
        return;
    result.notes.push_back("occlusion map (" + occlusionSource + ") in " + where);
}

ConeMap ExportJob::cones(ConeKind kind) {
    const ConeMap& loaded = kind == ConeKind::Conservative ? assets.cone : assets.relaxedCone;
    if (!loaded.sqrtRatio.empty())
        return loaded;
    result.notes.push_back(std::string(kind == ConeKind::Conservative ? "cone" : "relaxed cone") +
                           " map baked from the height map (the material has none)");
    return bakeConeMap(assets.height, material.wrap, kind);
}

} // namespace exporter

namespace {

// The maps each target reads from the material.
MapSet mapsFor(const Material& m, ExportFormat format) {
    if (format == ExportFormat::Package)
        return mapsUsed(m);
    // Engines shade with their own model: colour, normals (loaded or baked from height),
    // occlusion/roughness/metallic when there are files, height for their parallax.
    MapSet set = mapsPresent(m.maps);
    set.cone = set.relaxedCone = false;
    return set;
}

// Technique "auto" measures the cone techniques on the material's own cone maps where it has them;
// an occlusion bake reads the height map.
MapSet mapsToLoad(const Material& m, const ExportOptions& options) {
    MapSet set =
        m.autoQuality ? withAutoInputs(m, mapsFor(m, options.format)) : mapsFor(m, options.format);
    if (options.bakeOcclusion && m.maps.ao.empty())
        set.height = set.height || !m.maps.height.empty();
    return set;
}

// The occlusion map the export carries: the material's own, or (asked for, where it has none)
// one baked from the height map. Returns where it came from, for the notes.
Result<std::string> occlusionFor(const Material& m, const ExportOptions& options,
                                 MaterialAssets& assets, std::vector<std::string>& notes) {
    if (!m.maps.ao.empty())
        return std::filesystem::path(m.maps.ao).filename().string();
    if (!options.bakeOcclusion)
        return std::string();
    if (assets.height.empty()) {
        notes.push_back("no occlusion map baked: the material has no height map");
        return std::string();
    }
    OcclusionBakeOptions bake;
    bake.heightScale = m.heightScale;
    bake.wrap = m.wrap;
    bake.distance = options.occlusionDistance;
    Result<OcclusionMaps> maps =
        bakeOcclusion(assets.height, bake, OcclusionOutputs::AmbientOcclusion);
    if (!maps)
        return maps.error().prefixed("baking the occlusion map: ");
    assets.ao = std::move(maps->occlusion);
    notes.push_back("occlusion map baked from the height map (" +
                    std::to_string(occlusionDirections(bake)) + " directions, distance " +
                    (std::isfinite(bake.distance)
                         ? exporter::formatDecimal(static_cast<float>(bake.distance)) + " uv"
                         : std::string("unlimited")) +
                    ", height scale " + exporter::formatDecimal(m.heightScale) + ", " +
                    std::string(toString(m.wrap)) + ")");
    return std::string("baked here");
}

// The engine whose own march an "auto" export sizes (Unreal's is not published: none).
std::optional<EngineMarch> engineMarchOf(ExportFormat format) {
    if (format == ExportFormat::Godot)
        return EngineMarch::Godot;
    if (format == ExportFormat::Unity)
        return EngineMarch::Hdrp;
    return std::nullopt;
}

} // namespace

Result<ExportResult> exportMaterial(const Material& material, const std::string& materialFile,
                                    const ExportOptions& options) {
    // What the export reads is recorded, so that updating an earlier export never replaces or
    // removes one of its inputs (the editor's exports too; the command line has its own session).
    const InputSession session;
    if (!materialFile.empty()) {
        if (Status s = noteInput(materialFile, "the material file"); !s)
            return s.error();
    }
    if (Status s = noteMaterialMaps(material, materialFile); !s)
        return s.error();
    if (std::vector<MaterialProblem> problems = validateMaterial(material); !problems.empty())
        return Error{formatProblems(problems, materialFile.empty() ? material.name : materialFile)};
    // Everything that can fail on the input fails before the output folder is touched.
    Result<MaterialAssets> assets =
        loadMaterialAssets(material, materialFile, mapsToLoad(material, options), options.load);
    if (!assets)
        return assets.error();
    std::vector<std::string> occlusionNotes;
    Result<std::string> occlusion = occlusionFor(material, options, *assets, occlusionNotes);
    if (!occlusion)
        return occlusion.error();
    Result<ExportFolder> folder = ExportFolder::begin(options.outDir, options.force);
    if (!folder)
        return folder.error();

    // Technique "auto" is resolved here, on the maps being exported; what was chosen is recorded
    // in the notes and the export carries only what the chosen setting reads.
    Result<ResolvedAuto> resolved =
        resolveAutoTechnique(material, assets->height, assets->cone, assets->relaxedCone,
                             materialFile.empty() ? material.name : materialFile,
                             engineMarchOf(options.format), options.coneCacheDir);
    if (!resolved)
        return resolved.error();
    ExportResult result;
    if (!resolved->note.empty())
        result.notes.push_back(resolved->note);
    if (!material.heightDerivedFrom.empty())
        result.notes.push_back("the height map was derived from the normal map " +
                               material.heightDerivedFrom +
                               " by integrating its slopes: a guess at the relief, not a measured "
                               "one");
    if (material.heightRange && !assets->height.empty()) {
        const HeightRange r = *material.heightRange;
        result.notes.push_back("the height map's file values from " +
                               exporter::formatDecimal(r.lo) + " to " +
                               exporter::formatDecimal(r.hi) +
                               " are written as 0 to 1, as engines read heights; the height "
                               "scale is the depth of that whole range");
    }
    result.notes.insert(result.notes.end(), occlusionNotes.begin(), occlusionNotes.end());
    exporter::ExportJob job{resolved->material,
                            options,
                            std::move(*assets),
                            *folder,
                            result,
                            exporter::fileStem(material.name),
                            materialFile,
                            std::move(resolved->engineLayers),
                            *occlusion};
    Status written = success();
    switch (options.format) {
    case ExportFormat::Package:
        written = exporter::writePackage(job);
        break;
    case ExportFormat::Gltf:
        written = exporter::writeGltf(job);
        break;
    case ExportFormat::Godot:
        written = exporter::writeGodot(job);
        break;
    case ExportFormat::Unreal:
        written = exporter::writeUnreal(job);
        break;
    case ExportFormat::Unity:
        written = exporter::writeUnity(job);
        break;
    }
    if (!written)
        return written.error(); // the staging folder goes with `folder`
    Result<ExportFolder::Committed> committed = folder->commit(
        "export --format " + std::string(toString(options.format)) + " of " + material.name);
    if (!committed)
        return committed.error();
    result.folder = folder->target().string();
    result.files = std::move(committed->files);
    result.kept = std::move(committed->kept);
    return result;
}

} // namespace px

// parallax-cli export: a material (or a folder of height maps with one preset) out to the
// project's package, glTF, Godot, Unreal or Unity.

#include "Cli.h"
#include "CommonOptions.h"
#include "DistanceOption.h"
#include "parallax/export/BatchScan.h"
#include "parallax/export/Exporter.h"
#include "parallax/material/MapFileName.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/MaterialNames.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace px::cli {

namespace {

struct ExportCliOptions {
    std::string material;
    HeightOptions height; // --height ... stands in for --material
    std::string albedo, normal, ao, roughness, metallic, specular;
    std::string normalGreen = "opengl";
    std::optional<float> scale;
    std::optional<std::string> technique;
    AutoQuality autoQuality; // with --technique auto
    std::string name;
    std::string batch, preset;
    std::string format = "package";
    std::string out;
    bool force = false;
    int heightBits = 16;
    int normalBits = 8;
    std::string green = "opengl";
    ConeCacheOptions cache; // technique auto's bakes
    bool bakeAo = false;
    double aoDistance = INFINITY;
};

std::vector<std::string> names(std::span<const std::string_view> list) {
    return {list.begin(), list.end()};
}

ExportOptions exportOptions(const ExportCliOptions& o, const std::string& out) {
    ExportOptions options;
    options.format = *parseExportFormat(o.format);
    options.outDir = out;
    options.force = o.force;
    options.heightFormat = o.heightBits == 32 ? PixelFormat::Float : PixelFormat::UInt16;
    options.normalFormat = o.normalBits == 16 ? PixelFormat::UInt16 : PixelFormat::UInt8;
    options.packageGreen = *parseNormalGreen(o.green);
    options.load.allowLarge = o.height.allowLarge;
    options.load.normalize = o.height.normalize;
    options.coneCacheDir = o.cache.folder();
    options.bakeOcclusion = o.bakeAo;
    options.occlusionDistance = o.aoDistance;
    return options;
}

// The material the --height, --albedo, ... options describe: defaults for everything else.
Material materialFromOptions(const ExportCliOptions& o) {
    Material m;
    m.maps.height = o.height.file;
    m.maps.albedo = o.albedo;
    m.maps.normal = o.normal;
    m.maps.ao = o.ao;
    m.maps.roughness = o.roughness;
    m.maps.metallic = o.metallic;
    m.maps.specular = o.specular;
    m.heightChannel = parseHeightChannel(o.height.channel).value_or(HeightChannel::Red);
    m.heightIsDepth = o.height.invert;
    m.wrap = o.height.wrapMode();
    m.normalGreen = *parseNormalGreen(o.normalGreen);
    if (!o.normal.empty())
        m.normalSource = NormalSource::Map;
    if (o.scale)
        m.heightScale = *o.scale;
    if (o.technique == "auto") {
        m.autoQuality = o.autoQuality;
    } else if (o.technique) {
        m.technique = *parseTechnique(*o.technique);
        m.params = info(m.technique).defaults;
    }
    if (!o.ao.empty() || !o.roughness.empty() || !o.metallic.empty())
        m.lighting = LightingModel::MetallicRoughness;
    std::string name = o.name;
    if (name.empty()) { // bricks_height.png -> bricks, read as the import reads names
        const std::vector<NameReading> readings = readMapFileName(o.height.file);
        const NameReading& tagged = readings.front();
        name = tagged.tag && !tagged.glued ? tagged.stem : readings.back().stem;
        if (name.empty()) // the whole name is a tag (h.png, height.png): the user's name stays
            name = std::filesystem::path(o.height.file).stem().string();
    }
    m.name = name.empty() ? "material" : name;
    return m;
}

void printResult(const ExportResult& result, const std::string& format) {
    std::cout << "Exported " << format << " to " << result.folder << ":";
    for (const std::string& file : result.files)
        std::cout << " " << file;
    std::cout << "\n";
    for (const std::string& note : result.notes)
        std::cout << "note: " << note << "\n";
    if (!result.kept.empty()) {
        std::cout << "kept " << result.kept.size() << " file"
                  << (result.kept.size() == 1 ? "" : "s") << " that this export did not write:";
        for (const std::string& file : result.kept)
            std::cout << " " << file;
        std::cout << "\n";
    }
}

int runSingle(const ExportCliOptions& o) {
    Material material;
    std::string materialFile;
    if (!o.material.empty()) {
        Result<Material> loaded = loadMaterial(o.material);
        if (!loaded)
            return fail(loaded.error().message);
        material = std::move(*loaded);
        materialFile = o.material;
    } else {
        material = materialFromOptions(o);
    }
    Result<ExportResult> result = exportMaterial(material, materialFile, exportOptions(o, o.out));
    if (!result)
        return fail(result.error().message);
    printResult(*result, o.format);
    return 0;
}

int runBatch(const ExportCliOptions& o) {
    Result<Material> preset = loadMaterial(o.preset, MaterialCheck::Preset);
    if (!preset)
        return fail(preset.error().message);
    Result<BatchFolder> folder = scanBatchFolder(o.batch);
    if (!folder)
        return fail(folder.error().message);
    for (const SkippedFile& f : folder->unassigned)
        std::cout << "not in a set: " << std::filesystem::path(f.path).filename().string() << " ("
                  << f.why << ")\n";
    const std::size_t total = folder->items.size();
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < total; ++i) {
        const BatchItem& item = folder->items[i];
        std::cout << "[" << i + 1 << "/" << total << "] " << item.name << ": " << std::flush;
        // Each set as `import` reads it: the same roles, channels, height or depth and green.
        ExportOptions options =
            exportOptions(o, (std::filesystem::path(o.out) / item.name).string());
        Result<ImportedSet> set = importBatchItem(item, *preset, options.load);
        std::string problem = set ? "" : set.error().message;
        if (set) {
            const Material material = set->material;
            set->assets = {}; // the export reads the maps again, one set at a time
            Result<ExportResult> result = exportMaterial(material, "", options);
            if (result) {
                std::cout << "ok, " << result->files.size() << " files in " << result->folder
                          << "\n";
                for (const std::string& line : importSummary(*set)) {
                    if (!line.starts_with("Ignored: ")) // the set's own files only
                        std::cout << "  " << line << "\n";
                }
                for (const std::string& note : result->notes)
                    std::cout << "  note: " << note << "\n";
                continue;
            }
            problem = result.error().message;
        }
        std::cout << "failed\n";
        failures.push_back(item.name + ": " + problem);
    }
    std::cout << total << " texture set" << (total == 1 ? "" : "s") << ": "
              << total - failures.size() << " exported, " << failures.size() << " failed\n";
    for (const std::string& failure : failures)
        std::cerr << "error: " << failure << "\n";
    return failures.empty() ? 0 : 1;
}

int runExport(const ExportCliOptions& o) {
    const int sources = !o.material.empty() + !o.height.file.empty() + !o.batch.empty();
    if (sources != 1)
        return fail("give exactly one of --material FILE.json, --height FILE, or --batch DIR");
    if (!o.batch.empty() && o.preset.empty())
        return fail("--batch needs --preset FILE.json (the settings every material gets)");
    if (o.batch.empty() && !o.preset.empty())
        return fail("--preset goes with --batch");
    const bool mapOptions = !o.albedo.empty() || !o.normal.empty() || !o.ao.empty() ||
                            !o.roughness.empty() || !o.metallic.empty() || !o.specular.empty() ||
                            o.scale || o.technique || !o.name.empty();
    if (mapOptions && o.height.file.empty())
        return fail("--albedo, --normal, --scale, --technique ... go with --height (a material "
                    "file or preset already says them)");
    return o.batch.empty() ? runSingle(o) : runBatch(o);
}

std::vector<std::string> techniqueNames() {
    std::vector<std::string> list;
    for (const TechniqueInfo& t : allTechniques())
        list.emplace_back(t.name);
    list.emplace_back("auto");
    return list;
}

} // namespace

Action addExportCommand(CLI::App& app) {
    auto o = std::make_shared<ExportCliOptions>();
    CLI::App* cmd = app.add_subcommand(
        "export", "Export a material as a package (JSON, maps, shader) or for glTF, Godot, "
                  "Unreal or Unity; or a folder of height maps with one preset");
    cmd->add_option("--material", o->material, "Material file (.json)");
    o->height.addTo(*cmd, false);
    cmd->add_option("--albedo", o->albedo, "With --height: base colour map (sRGB)");
    cmd->add_option("--normal", o->normal, "With --height: normal map (else baked from height)");
    cmd->add_option("--normal-green", o->normalGreen, "With --normal: its green convention")
        ->check(CLI::IsMember(names(normalGreenNames())));
    cmd->add_option("--ao", o->ao, "With --height: ambient occlusion map");
    cmd->add_option("--roughness", o->roughness, "With --height: roughness map");
    cmd->add_option("--metallic", o->metallic, "With --height: metallic map");
    cmd->add_option("--specular", o->specular,
                    "With --height: specular map (glTF and Unreal read it; see docs/export.md)");
    cmd->add_option("--scale", o->scale, "With --height: height scale in uv units")
        ->check(inRange(0.0, 100.0));
    cmd->add_option("--technique", o->technique,
                    "With --height: technique, or auto (the cheapest meeting --budget up to "
                    "--max-polar, resolved on the exported maps)")
        ->check(CLI::IsMember(techniqueNames()));
    cmd->add_option("--budget", o->autoQuality.budget,
                    "With --technique auto: p99 hit error budget in texels (default 0.5)")
        ->check(inRange(0.0, 1e6));
    cmd->add_option("--max-polar", o->autoQuality.maxPolar,
                    "With --technique auto: steepest view angle, degrees (default 80)")
        ->check(inRange(0.0, 89.0));
    cmd->add_option("--name", o->name, "With --height: material name (default: from the file)");
    cmd->add_option("--batch", o->batch,
                    "Folder of texture sets (each read as import reads one: names, packing, "
                    "height or depth, green)");
    cmd->add_option("--preset", o->preset,
                    "With --batch: material file whose settings each "
                    "set gets (its maps are ignored)");
    cmd->add_option("--format", o->format, "package, gltf, godot, unreal or unity")
        ->check(CLI::IsMember(names(exportFormatNames())))
        ->required();
    cmd->add_option("--out", o->out, "Output folder (with --batch: one sub-folder per material)")
        ->required();
    cmd->add_flag("--force", o->force, "Replace an earlier export in the output folder");
    o->cache.addTo(*cmd);
    CLI::Option* bakeAo =
        cmd->add_flag("--bake-ao", o->bakeAo,
                      "Bake an occlusion map from the height map where the material has none "
                      "(the exact bake, default directions); every format with an occlusion slot "
                      "carries it");
    addDistanceOption(*cmd, "--ao-distance", o->aoDistance,
                      "With --bake-ao: how far a blocker may be, uv units, or inf (default)")
        ->needs(bakeAo);
    cmd->add_option("--height-bits", o->heightBits, "Height map: 16 (PNG) or 32 (float EXR)")
        ->check(CLI::IsMember({16, 32}));
    cmd->add_option("--normal-bits", o->normalBits, "Normal map: 8 or 16-bit PNG")
        ->check(CLI::IsMember({8, 16}));
    cmd->add_option("--green", o->green,
                    "Package only: normal map green, opengl (Y+) or directx (Y-); engine formats "
                    "use their own")
        ->check(CLI::IsMember(names(normalGreenNames())));
    return [o] { return runExport(*o); };
}

} // namespace px::cli

// parallax-cli bake normal|cone|relaxed-cone|pyramid|ao|bent-normal: the bakers of core/bake as
// files.
//
// Every bake is checked before it starts (options, output type, output folder), shows progress
// on stderr once it has run for a second, stops at once on Ctrl-C (Interrupt.h), and writes
// atomically: a failed or interrupted bake leaves any previous output untouched and no partial
// file.

#include "Cli.h"
#include "CommonOptions.h"
#include "MeshBakeCommand.h"
#include "ProgressLine.h"
#include "parallax/bake/BakeEncoding.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/bake/NormalMapBaker.h"
#include "parallax/bake/OcclusionBaker.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/FileExtension.h"
#include "parallax/material/MaterialNames.h"
#include "parallax/render/GpuConeBaker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

namespace px::cli {

namespace {

struct BakeOptions {
    std::string kind;
    HeightOptions height;
    float scale = 0.05f;
    std::string filter = "sobel";
    std::string green = "opengl";
    std::string normal;               // pass-through: a loaded normal map
    std::string normalGreen = "auto"; // its convention
    std::optional<int> bits;
    std::string layout = "atlas";
    int level = -1;
    bool gpu = false;
    std::string distance = "inf"; // ao, bent-normal: D in uv, or inf
    int directions = 0;           // ao, bent-normal: azimuths (0: the default)
    std::string out;
    MeshBakeCli mesh; // bake height|normal|ao --mesh (MeshBakeCommand.h)
};

bool isOcclusion(const std::string& kind) {
    return kind == "ao" || kind == "bent-normal";
}

// The pixel format from --bits and the extension, checked before any work is done.
Result<PixelFormat> outputFormat(const BakeOptions& o) {
    const std::string ext = lowerExtension(o.out);
    if (ext != ".png" && ext != ".tif" && ext != ".tiff" && ext != ".exr")
        return fileError(o.out, "unknown output type '" + ext + "': use .png, .tif or .exr");
    const bool eightBit = o.kind == "normal" || o.kind == "bent-normal";
    const int bits = o.bits.value_or(ext == ".exr" ? 32 : (eightBit ? 8 : 16));
    Result<PixelFormat> format = pixelFormatFromBits(bits);
    if (!format)
        return format;
    if (!extensionSupports(o.out, *format))
        return fileError(
            o.out, ext == ".exr"
                       ? "EXR stores float here: use --bits 32"
                       : "PNG stores 8 or 16 bits: use --bits 8 or 16, or a .tif/.exr for 32");
    const std::filesystem::path folder = std::filesystem::path(o.out).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
        return fileError(o.out, "cannot create the file: the folder " + folder.string() +
                                    " does not exist");
    return format;
}

// Options that only one kind of bake reads are errors elsewhere: silently ignoring them would
// hide a mistake (--scale on a cone map, say).
Status checkApplicable(const BakeOptions& o, const CLI::App& cmd) {
    struct Rule {
        const char* option;
        bool allowed;
    };
    const bool normal = o.kind == "normal", pyramid = o.kind == "pyramid";
    const bool occlusion = isOcclusion(o.kind), bent = o.kind == "bent-normal";
    for (const Rule& r :
         {Rule{"--scale", normal || occlusion}, Rule{"--filter", normal},
          Rule{"--green", normal || bent}, Rule{"--normal", normal}, Rule{"--normal-green", normal},
          Rule{"--layout", pyramid}, Rule{"--level", pyramid}, Rule{"--distance", occlusion},
          Rule{"--directions", occlusion}, Rule{"--gpu", !normal && !pyramid}}) {
        if (!r.allowed && cmd.count(r.option) > 0)
            return Error{std::string(r.option) + " does not apply to bake " + o.kind};
    }
    if (occlusion && cmd.count("--gpu") > 0)
        return Error{"--gpu: bake " + o.kind + " runs on the CPU only so far (leave out --gpu)"};
    if (o.normal.empty() && o.height.file.empty())
        return Error{"bake " + o.kind + " needs --height FILE" +
                     (normal ? " (or --normal FILE)" : "")};
    if (!o.normal.empty() && cmd.count("--filter") + cmd.count("--scale") > 0)
        return Error{"--filter and --scale apply to normals baked from --height, not to a loaded "
                     "--normal map"};
    if (!o.normal.empty() && o.normalGreen == "auto" && o.height.file.empty())
        return Error{
            "--normal-green auto tells the convention from the height map: give --height too, "
            "or say --normal-green opengl|directx"};
    return success();
}

Result<Image> bakeNormal(const BakeOptions& o, const BakeControl& control) {
    const NormalGreen green = *parseNormalGreen(o.green);
    if (!o.normal.empty()) {
        Result<Image> loaded = readImage(o.normal);
        if (!loaded)
            return loaded.error();
        NormalGreen from = NormalGreen::OpenGL;
        if (o.normalGreen == "auto") {
            Result<HeightField> field = o.height.load();
            if (!field)
                return field.error();
            Result<NormalGreen> told =
                detectNormalGreen(*loaded, *field, o.height.wrapMode(), o.normal);
            if (!told)
                return told.error();
            from = *told;
            std::fprintf(stderr, "%s: green is %s\n", o.normal.c_str(),
                         std::string(toString(from)).c_str());
        } else {
            from = *parseNormalGreen(o.normalGreen);
        }
        return convertNormalMap(*loaded, from, green, o.normal);
    }
    Result<HeightField> field = o.height.load();
    if (!field)
        return field.error();
    NormalBakeOptions options;
    options.heightScale = o.scale;
    options.filter = *parseNormalFilter(o.filter);
    options.wrap = o.height.wrapMode();
    options.green = green;
    return bakeNormalMap(*field, options, control);
}

Result<Image> bakeCones(const BakeOptions& o, PixelFormat format, const BakeControl& control) {
    // Bake from the heights as the file will store them, so that R and G agree (the loaded
    // heights go at once: an 8192² map's 256 MiB less at the peak).
    HeightField field;
    {
        Result<HeightField> source = o.height.load();
        if (!source)
            return source.error();
        field = roundHeightsUp(*source, format);
    }
    const ConeKind kind = o.kind == "cone" ? ConeKind::Conservative : ConeKind::Relaxed;
    // --gpu: the same kernels on a GPU context; asked for and not there is an error (a script
    // that asks for the GPU wants to know), never a silent CPU bake.
    GpuBakeInfo info;
    Result<ConeMap> cones =
        o.gpu ? bakeConeMapHeadless(field, o.height.wrapMode(), kind, control, &info)
              : bakeConeMap(field, o.height.wrapMode(), kind, control);
    if (o.gpu && !cones && !isCancelled(cones.error()))
        return Error{"--gpu: " + cones.error().message + " (bake without --gpu to use the CPU)"};
    if (o.gpu && cones)
        std::fprintf(stderr, "baked on the GPU (%s) in %.0f ms\n", info.renderer.c_str(),
                     info.milliseconds);
    if (!cones)
        return cones.error();
    return encodeConeMap(field, std::move(*cones), format);
}

// D from --distance: a number > 0 (uv) or inf; anything else is an error, never clamped.
Result<double> occlusionDistance(const std::string& text) {
    if (text == "inf")
        return std::numeric_limits<double>::infinity();
    std::size_t used = 0;
    double d = 0.0;
    try {
        d = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !std::isfinite(d) || !(d > 0.0))
        return Error{"--distance " + text + ": give a distance > 0 in uv units, or inf"};
    return d;
}

Result<Image> bakeOcclusionMap(const BakeOptions& o, double distance, const BakeControl& control) {
    Result<HeightField> field = o.height.load();
    if (!field)
        return field.error();
    OcclusionBakeOptions options;
    options.heightScale = o.scale;
    options.distance = distance;
    options.directions = o.directions;
    options.wrap = o.height.wrapMode();
    options.green = *parseNormalGreen(o.green);
    const bool ao = o.kind == "ao";
    Result<OcclusionMaps> maps = bakeOcclusion(
        *field, options, ao ? OcclusionOutputs::AmbientOcclusion : OcclusionOutputs::BentNormals,
        control);
    if (!maps)
        return maps.error();
    return ao ? std::move(maps->occlusion) : std::move(maps->bentNormals);
}

Result<Image> bakePyramid(const BakeOptions& o, PixelFormat format) {
    Result<HeightField> field = o.height.load();
    if (!field)
        return field.error();
    const MaxMipPyramid pyramid = MaxMipPyramid::build(*field, o.height.wrapMode());
    if (o.level >= pyramid.levels())
        return Error{"--level " + std::to_string(o.level) +
                     " does not exist: the pyramid has levels 0 to " +
                     std::to_string(pyramid.top())};
    const PyramidLayout layout = o.layout == "chain" ? PyramidLayout::Chain : PyramidLayout::Atlas;
    return encodePyramid(pyramid, layout, o.level, format);
}

int runBake(const BakeOptions& o, const CLI::App& cmd) {
    if (o.mesh.asked(o.kind)) {
        if (o.kind != "height" && o.kind != "normal" && o.kind != "ao")
            return fail("bake " + o.kind +
                        " bakes from a height map; a --mesh bakes height, "
                        "normal or ao");
        Result<PixelFormat> format = outputFormat(o);
        if (!format)
            return fail(format.error().message);
        // --distance is the occlusion bakes' own option: here in the mesh's units.
        const Result<double> distance = occlusionDistance(o.distance);
        if (!distance)
            return fail(distance.error().message);
        return runMeshBake(o.mesh, {o.kind, o.height.wrap, o.green, *format, o.out, *distance},
                           cmd);
    }
    if (Status s = o.mesh.checkNotGiven(o.kind, cmd); !s)
        return fail(s.error().message);
    if (Status s = checkApplicable(o, cmd); !s)
        return fail(s.error().message);
    Result<PixelFormat> format = outputFormat(o);
    if (!format)
        return fail(format.error().message);
    const Result<double> distance = occlusionDistance(o.distance);
    if (!distance)
        return fail(distance.error().message);

    Result<Image> image = Error{""};
    {
        ProgressLine line("baking " + o.kind + (o.kind == "pyramid" ? "" : " map"));
        BakeControl control;
        control.progress = [&line](float done) { line(done); };
        if (o.kind == "normal")
            image = bakeNormal(o, control);
        else if (o.kind == "pyramid")
            image = bakePyramid(o, *format);
        else if (isOcclusion(o.kind))
            image = bakeOcclusionMap(o, *distance, control);
        else
            image = bakeCones(o, *format, control);
    }
    if (!image)
        return fail(image.error().message);
    ImageWriteOptions write;
    write.format = *format;
    if (Status s = writeImage(o.out, *image, write); !s)
        return fail(s.error().message);
    return 0;
}

} // namespace

Action addBakeCommand(CLI::App& app) {
    auto o = std::make_shared<BakeOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bake", "Bake a normal, cone, relaxed cone, max-mip, ambient occlusion or bent normal map "
                "from a height map, or height, normal and occlusion maps from a sculpted tile "
                "(--mesh)");
    cmd->add_option("kind", o->kind,
                    "normal, cone, relaxed-cone, pyramid, ao or bent-normal from a height map; "
                    "height, normal or ao from a --mesh")
        ->required()
        ->check(CLI::IsMember(
            {"height", "normal", "cone", "relaxed-cone", "pyramid", "ao", "bent-normal"}));
    o->height.addTo(*cmd, false);
    cmd->add_option("--scale", o->scale,
                    "normal, ao, bent-normal: height scale s in uv units (the material's "
                    "height_scale)")
        ->check(inRange(0.0, 100.0));
    std::vector<std::string> filters(normalFilterNames().begin(), normalFilterNames().end());
    cmd->add_option("--filter", o->filter, "normal: derivative filter (default sobel)")
        ->check(CLI::IsMember(filters));
    cmd->add_option("--green", o->green,
                    "normal, bent-normal: green of the output, opengl (Y+) or directx (Y-)")
        ->check(CLI::IsMember({"opengl", "directx"}));
    cmd->add_option("--normal", o->normal,
                    "normal: pass a loaded normal map through instead of baking one");
    cmd->add_option("--normal-green", o->normalGreen,
                    "normal: green of the --normal map (auto: told from --height)")
        ->check(CLI::IsMember({"auto", "opengl", "directx"}));
    cmd->add_option("--bits", o->bits,
                    "8, 16 or 32 (float); default 32 for .exr, else 8 (normal, bent-normal) or 16")
        ->check(CLI::IsMember({8, 16, 32}));
    cmd->add_option("--layout", o->layout,
                    "pyramid: atlas (every level stacked, for the GPU) or chain (for looking at)")
        ->check(CLI::IsMember({"atlas", "chain"}));
    cmd->add_option("--level", o->level, "pyramid: write one level only")->check(inRange(0, 64));
    cmd->add_option("--distance", o->distance,
                    "ao, bent-normal: how far (uv; with --mesh, mesh units) a blocker may be; inf "
                    "(default): unlimited");
    cmd->add_option("--directions", o->directions,
                    "ao, bent-normal: azimuths (default " +
                        std::to_string(kDefaultOcclusionDirections) + ")")
        ->check(inRange(1, kMaxOcclusionDirections));
    cmd->add_flag("--gpu", o->gpu,
                  "cone, relaxed-cone: bake on the GPU (the same kernels, the same map; an "
                  "error where no OpenGL 4.3 context can be made)");
    o->mesh.addTo(*cmd);
    cmd->add_option("--out", o->out, "Output image: .png, .tif or .exr (format from the extension)")
        ->required();
    return [o, cmd] { return runBake(*o, *cmd); };
}

} // namespace px::cli

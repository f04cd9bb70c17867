#include "MeshBakeCommand.h"

#include "Cli.h"
#include "CommonOptions.h"
#include "ProgressLine.h"
#include "parallax/io/FileExtension.h"
#include "parallax/io/Inputs.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/meshbake/MeshBake.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace px::cli {

namespace {

namespace fs = std::filesystem;

// Options of the bakes from a height map: an error on a mesh bake, never silently ignored.
constexpr const char* kHeightMapOptions[] = {
    "--height", "--invert", "--normalize", "--allow-large",  "--channel",
    "--scale",  "--filter", "--normal",    "--normal-green", "--layout",
    "--level",  "--gpu",    "--directions"};
constexpr const char* kMeshOptions[] = {"--mesh-root", "--tile",    "--up",   "--range",
                                        "--size",      "--samples", "--rays", "--material"};

// "a,b,c": exactly `count` finite decimal numbers.
Result<std::vector<double>> numbers(const std::string& text, std::size_t count,
                                    const std::string& option, const std::string& form) {
    std::vector<double> values;
    const char* at = text.data();
    const char* end = text.data() + text.size();
    while (at <= end) {
        const char* comma = std::find(at, end, ',');
        double v = 0;
        auto [stop, ec] = std::from_chars(at, comma, v);
        if (ec != std::errc{} || stop != comma || !std::isfinite(v))
            return Error{option + ": expected " + form + ", got \"" + text + "\""};
        values.push_back(v);
        at = comma + 1;
    }
    if (values.size() != count)
        return Error{option + ": expected " + form + ", got \"" + text + "\""};
    return values;
}

Result<std::pair<int, int>> parseSize(const std::string& text) {
    auto number = [](std::string_view s, int& out) {
        auto [stop, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        return ec == std::errc{} && stop == s.data() + s.size() && out >= 1 && out <= 32768;
    };
    const std::size_t x = text.find('x');
    int w = 0, h = 0;
    const bool ok = x == std::string::npos ? number(text, w) && (h = w, true)
                                           : number(std::string_view(text).substr(0, x), w) &&
                                                 number(std::string_view(text).substr(x + 1), h);
    if (!ok)
        return Error{"--size: expected N or WxH with sides 1 to 32768, got \"" + text + "\""};
    return std::pair{w, h};
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// The material to update: the existing file (read, not recorded as an input: it is an output of
// this run), or a new one named after the mesh.
Result<Material> materialToUpdate(const std::string& path, const std::string& mesh) {
    if (lowerExtension(path) != ".json")
        return fileError(path, "a material file ends in .json");
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        Material m;
        m.name = fs::path(mesh).stem().string();
        m.technique = Technique::None;
        m.normalSource = NormalSource::None;
        return m;
    }
    Result<InputFile> file = InputFile::open(path, "--material", false);
    if (!file)
        return file.error();
    Result<std::string> text = file->readAll(1 << 20);
    if (!text)
        return text.error();
    return parseMaterial(*text, path, MaterialCheck::Preset);
}

// The baked map joins the material, with the scale and wrap of this bake; the technique and
// normal source follow the maps it has.
Material withMap(Material m, const MeshBakeOutput& o, const std::string& path, double scale,
                 NormalGreen green) {
    std::error_code ec;
    const fs::path folder = fs::absolute(path, ec).parent_path();
    const std::string map = fs::absolute(o.out, ec).lexically_relative(folder).generic_string();
    if (o.kind == "height")
        m.maps.height = map;
    else if (o.kind == "normal")
        m.maps.normal = map;
    else
        m.maps.ao = map;
    m.heightScale = static_cast<float>(scale);
    m.heightIsDepth = false;
    m.heightRange.reset();
    m.wrap = parseWrapMode(o.wrap).value_or(WrapMode::Repeat);
    if (o.kind == "normal")
        m.normalGreen = green;
    if (!m.maps.normal.empty())
        m.normalSource = NormalSource::Map;
    else if (!m.maps.height.empty() && m.normalSource == NormalSource::None)
        m.normalSource = NormalSource::HeightCentral;
    if (!m.maps.height.empty() && m.technique == Technique::None)
        m.technique = Technique::Pom;
    else if (m.maps.height.empty())
        m.technique = m.maps.normal.empty() ? Technique::None : Technique::Normal;
    return m;
}

} // namespace

void MeshBakeCli::addTo(CLI::App& command) {
    command.add_option("--mesh", mesh,
                       "height, normal, ao: bake from a mesh (OBJ, PLY, STL, glTF/GLB, FBX) "
                       "instead of a height map");
    command.add_option("--mesh-root", root,
                       "mesh: the folder the files a mesh refers to must lie under (default: "
                       "the mesh's own folder)");
    command.add_option("--tile", tile,
                       "mesh: the tile x0,y0,x1,y1 in the mesh's XY plane (default: its bounds)");
    command.add_option("--up", up, "mesh: the file's up axis; y reads it as seen from +Y")
        ->check(CLI::IsMember({"z", "y"}));
    command.add_option("--range", range,
                       "mesh: heights z0,z1 mapped to 0..1 (default: the range of the hits)");
    command.add_option("--size", size, "mesh: the maps' size, N or WxH (default 1024)");
    command.add_option("--samples", samples, "mesh: K x K sub-samples per texel (default 1)")
        ->check(inRange(1, 16));
    command.add_option("--rays", rays, "ao from a mesh: rays per texel (default 64)")
        ->check(inRange(1, 4096));
    command.add_option("--material", material,
                       "mesh: write (or update) a material JSON with the map and the height scale");
}

bool MeshBakeCli::asked(const std::string& kind) const {
    return !mesh.empty() || kind == "height";
}

Status MeshBakeCli::checkNotGiven(const std::string& kind, const CLI::App& command) const {
    for (const char* option : kMeshOptions) {
        if (command.count(option) > 0)
            return Error{std::string(option) + " applies to bakes from a --mesh, not to bake " +
                         kind + " from a height map"};
    }
    return success();
}

int runMeshBake(const MeshBakeCli& m, const MeshBakeOutput& o, const CLI::App& command) {
    for (const char* option : kHeightMapOptions) {
        if (command.count(option) > 0)
            return fail(std::string(option) + " does not apply to bake " + o.kind + " --mesh");
    }
    if (m.mesh.empty())
        return fail("bake " + o.kind + " needs --mesh FILE");
    if (o.kind != "ao" && command.count("--rays") + command.count("--distance") > 0)
        return fail("--rays and --distance apply to bake ao, not to bake " + o.kind);
    if (o.kind != "normal" && command.count("--green") > 0)
        return fail("--green applies to bake normal, not to bake " + o.kind);

    MeshBakeOptions options;
    Result<std::pair<int, int>> size = parseSize(m.size);
    if (!size)
        return fail(size.error().message);
    options.width = size->first;
    options.height = size->second;
    options.samples = m.samples;
    options.rays = m.rays;
    options.distance = o.distance;
    options.wrap = parseWrapMode(o.wrap).value_or(WrapMode::Repeat);
    options.green = o.green == "directx" ? NormalGreen::DirectX : NormalGreen::OpenGL;
    options.maps = {o.kind == "height", o.kind == "normal", o.kind == "ao"};
    if (!m.range.empty()) {
        Result<std::vector<double>> r = numbers(m.range, 2, "--range", "z0,z1");
        if (!r)
            return fail(r.error().message);
        if (!((*r)[1] > (*r)[0]))
            return fail("--range: expected z0 < z1, got \"" + m.range + "\"");
        options.range = HeightRangeZ{(*r)[0], (*r)[1]};
    }
    std::optional<BakeTile> tile;
    if (!m.tile.empty()) {
        Result<std::vector<double>> t = numbers(m.tile, 4, "--tile", "x0,y0,x1,y1");
        if (!t)
            return fail(t.error().message);
        if (!((*t)[2] > (*t)[0] && (*t)[3] > (*t)[1]))
            return fail("--tile: expected x0 < x1 and y0 < y1, got \"" + m.tile + "\"");
        tile = BakeTile{(*t)[0], (*t)[1], (*t)[2], (*t)[3]};
    }
    std::optional<Material> material;
    if (!m.material.empty()) {
        Result<Material> existing = materialToUpdate(m.material, m.mesh);
        if (!existing)
            return fail(existing.error().message);
        // Refused now, before the bake, rather than after the map is written.
        const std::vector<MaterialProblem> problems =
            validateMaterial(withMap(*existing, o, m.material, 0.05, NormalGreen::OpenGL));
        if (!problems.empty())
            return fail(formatProblems(problems, m.material));
        material = std::move(*existing);
    }

    const auto started = std::chrono::steady_clock::now();
    Result<BakeMesh> mesh = Error{""};
    {
        ProgressLine line("reading " + m.mesh);
        BakeMeshLoadOptions load;
        load.up = m.up == "y" ? MeshUp::Y : MeshUp::Z;
        load.root = m.root;
        load.progress = [&line](float done) {
            line(done);
            return true;
        };
        mesh = loadBakeMesh(m.mesh, load);
    }
    if (!mesh)
        return fail(mesh.error().message);
    std::printf("%s: %zu triangles, %zu vertices (%s normals), read in %.2f s\n", m.mesh.c_str(),
                mesh->triangleCount(), mesh->vertexCount(),
                mesh->normals.empty() ? "face" : "vertex", seconds(started));
    for (const std::string& note : mesh->notes)
        std::printf("%s\n", note.c_str());
    options.tile = tile.value_or(defaultTile(*mesh));
    if (!tile)
        std::printf("tile %g,%g,%g,%g (the mesh's XY bounds)\n", options.tile.x0, options.tile.y0,
                    options.tile.x1, options.tile.y1);
    if (Status s = checkMeshBake(*mesh, options); !s)
        return fail(s.error().message);

    const auto baking = std::chrono::steady_clock::now();
    Result<MeshBakeResult> baked = Error{""};
    {
        ProgressLine line("baking " + o.kind + " map from " + m.mesh);
        BakeControl control;
        control.progress = [&line](float done) { line(done); };
        baked = bakeFromMesh(*mesh, options, control);
    }
    if (!baked)
        return fail(baked.error().message);
    std::printf("baked %dx%d (%d x %d samples a texel, %d cop%s of the mesh) in %.2f s\n",
                options.width, options.height, options.samples, options.samples, baked->copies,
                baked->copies == 1 ? "y" : "ies", seconds(baking));
    std::printf("heights z = %g to %g%s; height scale %g (uv units: (z1 - z0) / tile width)\n",
                baked->range.z0, baked->range.z1, options.range ? "" : " (the hits' range)",
                baked->heightScale);
    std::printf("%lld of %lld samples missed the mesh (given the range's minimum); %lld have "
                "overhangs (surfaces under the top one)\n",
                static_cast<long long>(baked->misses), static_cast<long long>(baked->samples),
                static_cast<long long>(baked->overhangs));

    const Image& image = o.kind == "height"   ? baked->height
                         : o.kind == "normal" ? baked->normal
                                              : baked->occlusion;
    ImageWriteOptions write;
    write.format = o.format;
    if (Status s = writeImage(o.out, image, write); !s)
        return fail(s.error().message);
    if (material) {
        if (Status s = saveMaterial(
                withMap(std::move(*material), o, m.material, baked->heightScale, options.green),
                m.material);
            !s)
            return fail(s.error().message);
        std::printf("%s: %s map and height scale %g\n", m.material.c_str(), o.kind.c_str(),
                    baked->heightScale);
    }
    return 0;
}

} // namespace px::cli

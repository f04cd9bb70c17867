// parallax-cli render: one frame of a material on a preview mesh, headless (EGL), as an image.

#include "Cli.h"
#include "CommonOptions.h"
#include "parallax/NumberText.h"
#include "parallax/eval/AutoTechnique.h"
#include "parallax/image/ImageFile.h"
#include "parallax/image/ImageSet.h"
#include "parallax/io/Inputs.h"
#include "parallax/light/Environment.h"
#include "parallax/light/EnvironmentLighting.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/MaterialNames.h"
#include "parallax/mesh/MeshLoader.h"
#include "parallax/render/FrameTimer.h"
#include "parallax/render/HeadlessContext.h"
#include "parallax/render/Renderer.h"
#include "parallax/shader/VariantKey.h"
#include "parallax/trace/Tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace px::cli {

namespace {

struct RenderOptions {
    std::string material;
    HeightOptions height;
    std::string albedo;
    std::string normal;
    std::optional<float> scale;
    std::optional<std::string> technique;
    QualityOptions quality;
    std::optional<std::string> normalSource;
    std::string normalGreen = "opengl";
    std::optional<std::string> lighting;
    bool shadow = false;
    std::optional<float> softness;
    std::optional<float> tiling;
    std::string mesh = "plane";
    std::optional<int> uvSet;
    std::size_t maxTriangles = kDefaultMaxMeshTriangles;
    std::string meshRoot; // where the mesh's references may lie (default: its folder)
    bool derivativeTbn = false;
    std::string size = "512x512";
    std::string light = "135,40";
    std::string camera;
    std::string background = "0,0,0,0";
    std::string environment; // "sky" or a file
    float exposure = 0.0f;
    int timeFrames = 0;
    int turntable = 0; // frames around the mesh; 0: one picture
    KernelOptions kernels;
    ConeCacheOptions cache; // technique auto's bakes
    std::string out;
};

// "A,B,C" into exactly `n` finite numbers, or a sentence about `what` (NumberText.h's words for
// a part that is no finite number).
Result<std::vector<float>> numbers(const std::string& text, std::size_t n,
                                   const std::string& what) {
    std::vector<float> values;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');) {
        Result<double> v = parseReal(part, what, {-3.0e38, 3.0e38});
        if (!v)
            return v.error();
        values.push_back(static_cast<float>(*v));
    }
    if (values.size() != n || text.ends_with(','))
        return Error{what + " \"" + text + "\" is not " + std::to_string(n) +
                     " numbers separated by commas"};
    return values;
}

// "512" (square) or "WIDTHxHEIGHT", each side 1 to 16384.
Result<glm::ivec2> parseSize(const std::string& text) {
    const std::size_t x = text.find('x');
    Result<long long> w = parseInteger(text.substr(0, x), "--size", 1, 16384);
    if (!w)
        return w.error();
    if (x == std::string::npos)
        return glm::ivec2(static_cast<int>(*w));
    Result<long long> h = parseInteger(text.substr(x + 1), "--size", 1, 16384);
    if (!h)
        return h.error();
    return glm::ivec2(static_cast<int>(*w), static_cast<int>(*h));
}

// Default orbit distance: the mesh fills about two thirds of the frame.
float defaultDistance(MeshKind mesh) {
    switch (mesh) {
    case MeshKind::Plane:
        return 3.6f;
    case MeshKind::Cube:
        return 4.0f;
    case MeshKind::Sphere:
        return 3.6f;
    case MeshKind::Cylinder:
        return 3.8f;
    }
    return 3.6f;
}

Result<Material> materialFrom(const RenderOptions& o, MaterialAssets& assets) {
    Material m;
    if (!o.material.empty()) {
        Result<Material> loaded = loadMaterial(o.material);
        if (!loaded)
            return loaded.error();
        m = *loaded;
    }
    if (o.technique)
        m.autoQuality.reset(); // a technique named on the command line replaces "auto"
    if (o.technique && *parseTechnique(*o.technique) != m.technique) {
        // Another technique than the material's: its own default parameters.
        m.technique = *parseTechnique(*o.technique);
        m.params = info(m.technique).defaults;
    }
    if (!m.autoQuality) { // with "auto" the quality options adjust the choice (below)
        o.quality.applyTo(m.params);
        if (Status s = validate(m.params); !s)
            return s.error();
    }
    if (o.scale)
        m.heightScale = *o.scale;
    if (o.normalSource)
        m.normalSource = *parseNormalSourceShortName(*o.normalSource);
    else if (o.material.empty() && !o.normal.empty())
        m.normalSource = NormalSource::Map;
    m.normalGreen = o.normalGreen == "directx" ? NormalGreen::DirectX : NormalGreen::OpenGL;
    if (o.lighting)
        m.lighting = *parseLightingModel(*o.lighting);
    if (o.shadow)
        m.selfShadow = true;
    if (o.softness)
        m.shadowSoftness = *o.softness;
    if (o.tiling)
        m.tiling = *o.tiling;

    if (!o.material.empty()) {
        // Only the maps this view reads: no cone map unless cone/relaxed-cone asks for one (with
        // "auto", also those the measurement reads, loaded once).
        const MapSet which = m.autoQuality ? withAutoInputs(m, mapsUsed(m)) : mapsUsed(m);
        Result<MaterialAssets> loaded = loadMaterialAssets(m, o.material, which);
        if (!loaded)
            return loaded.error();
        if (m.autoQuality) {
            // Technique "auto": measured on this material's height map, as export resolves it;
            // then only the cone maps the chosen setting reads are kept.
            Result<ResolvedAuto> resolved =
                resolveAutoTechnique(m, loaded->height, loaded->cone, loaded->relaxedCone,
                                     o.material, std::nullopt, o.cache.folder());
            if (!resolved)
                return resolved.error();
            m = resolved->material;
            std::cout << "note: " << resolved->note << "\n";
            o.quality.applyTo(m.params); // --layers and the like adjust the chosen setting
            if (Status s = validate(m.params); !s)
                return s.error();
            const MapSet used = mapsUsed(m);
            if (!used.cone)
                loaded->cone = ConeMap{};
            if (!used.relaxedCone)
                loaded->relaxedCone = ConeMap{};
        }
        assets = std::move(*loaded);
        return m;
    }
    m.wrap = o.height.wrapMode();
    m.maps.height = o.height.file;
    Result<HeightField> field = o.height.load();
    if (!field)
        return field.error();
    assets.height = std::move(*field);
    if (!o.albedo.empty()) {
        Result<Image> albedo = readImage(o.albedo, colourMapReading());
        if (!albedo)
            return albedo.error();
        assets.albedo = std::move(*albedo);
        m.maps.albedo = o.albedo;
    }
    if (!o.normal.empty()) {
        Result<Image> normal = readImage(o.normal);
        if (!normal)
            return normal.error();
        if (normal->channels < 3)
            return Error{fileError(o.normal, "a normal map needs 3 channels, this has " +
                                                 std::to_string(normal->channels))};
        assets.normal = std::move(*normal);
        m.maps.normal = o.normal;
    }
    return m;
}

int runRender(const RenderOptions& o) {
    if (o.material.empty() && o.height.file.empty())
        return fail("give --material FILE.json or --height FILE");
    Result<glm::ivec2> size = parseSize(o.size);
    if (!size)
        return fail(size.error().message);
    Result<std::vector<float>> light = numbers(o.light, 2, "--light");
    if (!light)
        return fail(light.error().message);
    // The environment behind the mesh, or a colour.
    const bool showEnvironment = o.background == "environment";
    if (showEnvironment && o.environment.empty())
        return fail("--background environment needs --environment FILE or sky");
    Result<std::vector<float>> background =
        showEnvironment ? Result<std::vector<float>>(std::vector<float>(4, 0.0f))
                        : numbers(o.background, 4, "--background");
    if (!background)
        return fail(background.error().message);
    std::optional<PrefilteredEnvironment> environment;
    if (!o.environment.empty()) {
        // The built-in sky puts its sun where the light is: the sun that shadows is in the sky.
        Result<Image> map =
            o.environment == "sky"
                ? Result<Image>(makeSkyEnvironment(directionFromAngles((*light)[0], (*light)[1])))
                : loadEnvironment(o.environment);
        if (!map)
            return fail(map.error().message);
        environment = prefilterEnvironment(*map);
    }
    // A built-in mesh by name, else a file; a loaded mesh is fitted into the unit sphere, framed
    // as the sphere is.
    const std::optional<MeshKind> builtIn = parseMeshKind(o.mesh);
    if (builtIn && o.uvSet)
        return fail("--uv-set applies to a mesh file, not the built-in " + o.mesh);
    std::shared_ptr<const MeshData> loadedMesh;
    if (!builtIn) {
        MeshLoadOptions load;
        load.uvSet = o.uvSet.value_or(0);
        load.maxTriangles = o.maxTriangles;
        load.root = o.meshRoot;
        Result<LoadedMesh> mesh = loadMesh(o.mesh, load);
        if (!mesh)
            return fail(mesh.error().message);
        for (const std::string& note : mesh->notes)
            std::cout << "note: " << note << "\n";
        std::cout << "mesh: " << mesh->summary() << "\n";
        loadedMesh = std::make_shared<const MeshData>(std::move(mesh->mesh));
    }
    const MeshKind mesh = builtIn.value_or(MeshKind::Sphere);
    OrbitCamera camera;
    camera.distance = defaultDistance(mesh);
    if (!o.camera.empty()) {
        Result<std::vector<float>> c = numbers(o.camera, 3, "--camera");
        if (!c)
            return fail(c.error().message);
        if ((*c)[2] <= 0.0f)
            return fail("--camera: the distance must be positive");
        camera.azimuthDeg = (*c)[0];
        camera.elevationDeg = (*c)[1];
        camera.distance = (*c)[2];
    }
    if (!extensionSupports(o.out, PixelFormat::UInt8))
        return fail(
            fileError(o.out, "cannot hold an 8-bit image (use .png, .tif, .jpg, .bmp or .tga)")
                .message);

    // A turntable's frames are outputs too: no file the run reads (a map of the material) may be
    // one of them, which is refused as soon as it is met.
    const std::vector<std::string> frames =
        o.turntable > 0 ? numberedFiles(o.out, o.turntable) : std::vector<std::string>{};
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (Status s = planOutput(frames[i], "frame " + std::to_string(i) + " of --turntable"); !s)
            return fail(s.error().message);
    }
    MaterialAssets assets;
    Result<Material> material = materialFrom(o, assets);
    if (!material)
        return fail(material.error().message);

    Result<std::unique_ptr<HeadlessContext>> context = HeadlessContext::create();
    if (!context)
        return fail(context.error().message);
    Result<std::unique_ptr<Renderer>> renderer = Renderer::create();
    if (!renderer)
        return fail(renderer.error().message);
    Result<std::unique_ptr<GpuMaterial>> gpu = GpuMaterial::create(assets, material->wrap);
    if (!gpu)
        return fail(gpu.error().message);

    DirectionalLight sun;
    sun.azimuthDeg = (*light)[0];
    sun.elevationDeg = (*light)[1];
    std::unique_ptr<GpuEnvironment> gpuEnvironment;
    if (environment) {
        Result<std::unique_ptr<GpuEnvironment>> made = GpuEnvironment::create(*environment);
        if (!made)
            return fail(made.error().message);
        gpuEnvironment = std::move(*made);
    }
    DrawOptions options;
    options.environment = gpuEnvironment.get();
    options.exposure = o.exposure;
    options.showEnvironment = showEnvironment;
    options.mesh = mesh;
    options.customMesh = loadedMesh;
    options.tbn = o.derivativeTbn ? TbnSource::Derivatives : TbnSource::VertexTangents;
    options.background = {(*background)[0], (*background)[1], (*background)[2], (*background)[3]};
    options.kernels = o.kernels.flavour();
    ImageWriteOptions write;
    write.format = PixelFormat::UInt8;
    write.srgb = true;
    if (o.turntable > 0) {
        // The camera orbits once, the light and environment stay: OUT-000.png, OUT-001.png, ...
        // written as one set (ImageSet.h): a failure leaves the previous frames as they were.
        const Status written = writeImageSet(
            frames,
            [&](int i) {
                OrbitCamera turned = camera;
                turned.azimuthDeg = camera.azimuthDeg + 360.0f * static_cast<float>(i) /
                                                            static_cast<float>(o.turntable);
                return (*renderer)->renderImage(**gpu, *material, turned, sun, options, *size);
            },
            write);
        if (!written)
            return fail(written.error().message);
        std::printf("wrote %d turntable frames: %s ... %s\n", o.turntable, frames.front().c_str(),
                    frames.back().c_str());
        return 0;
    }
    Result<Image> image = (*renderer)->renderImage(**gpu, *material, camera, sun, options, *size);
    if (!image)
        return fail(image.error().message);
    if (Status s = writeImage(o.out, *image, write); !s)
        return fail(s.error().message);
    if (o.timeFrames > 0) {
        Result<RenderTarget> target = RenderTarget::create(*size, TargetFormat::Rgba8);
        if (!target)
            return fail(target.error().message);
        target->bind();
        // Both flavours in one run, the one drawn first: their ratio is what an engine saves.
        const KernelFlavour drawn = options.kernels;
        const KernelFlavour other =
            drawn == KernelFlavour::Production ? KernelFlavour::Verify : KernelFlavour::Production;
        double median[2] = {0.0, 0.0};
        for (KernelFlavour flavour : {drawn, other}) {
            DrawOptions timed = options;
            timed.kernels = flavour;
            Status status = success();
            const FrameTiming t = px::timeFrames(
                [&] {
                    if (status)
                        status = (*renderer)->draw(**gpu, *material, camera, sun, timed, *size);
                },
                o.timeFrames, 1, (*renderer)->glInfo());
            if (!status)
                return fail(status.error().message);
            median[static_cast<int>(flavour)] = t.medianMs;
            std::printf("%s %dx%d: median %.2f ms, min %.2f, max %.2f over %d frames (%s kernels, "
                        "%s, %s)\n",
                        info(material->technique).name.data(), size->x, size->y, t.medianMs,
                        t.minMs, t.maxMs, t.frames, shader::kernelFlavourName(flavour).data(),
                        t.method().c_str(), (*renderer)->glInfo().renderer.c_str());
        }
        std::printf("production / verify frame time: %.3f\n",
                    median[1] > 0.0 ? median[0] / median[1] : 0.0);
        const GlInfo& gl = (*context)->info();
        std::printf("GL: %s; vendor %s; %s\n", gl.summary().c_str(), gl.vendor.c_str(),
                    (*context)->platform().c_str());
    }
    return 0;
}

} // namespace

Action addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a material on a preview mesh without a display (OpenGL 4.3 through EGL)");
    auto* material = cmd->add_option("--material", o->material, "Material file (.json)");
    o->height.addTo(*cmd, false);
    auto* height = cmd->get_option("--height");
    material->excludes(height);
    cmd->add_option("--albedo", o->albedo, "Albedo map (sRGB), with --height")->excludes(material);
    cmd->add_option("--normal", o->normal, "Tangent-space normal map, with --height")
        ->excludes(material);
    cmd->add_option("--normal-green", o->normalGreen,
                    "Green of the normal map: opengl (Y+) or directx (Y-)")
        ->check(CLI::IsMember({"opengl", "directx"}));
    cmd->add_option("--scale", o->scale, "Height scale s in uv units")->check(inRange(0.0, 100.0));
    std::vector<std::string> techniques;
    for (const TechniqueInfo& t : allTechniques())
        techniques.emplace_back(t.name);
    cmd->add_option("--technique", o->technique, "Technique (default: the material's, else pom)")
        ->check(CLI::IsMember(techniques));
    o->quality.addTo(*cmd);
    cmd->add_option("--normal-source", o->normalSource,
                    "Shading normals: none, map, central, sobel")
        ->check(CLI::IsMember(choices(normalSourceShortNames())));
    cmd->add_option("--lighting", o->lighting, "blinn-phong or metallic-roughness")
        ->check(CLI::IsMember(choices(lightingModelNames())));
    cmd->add_flag("--shadow", o->shadow, "Soft self-shadowing towards the light");
    cmd->add_option("--softness", o->softness, "Shadow softness, 0 (hard) to 1")
        ->check(inRange(0.0, 1.0));
    cmd->add_option("--tiling", o->tiling, "Texture repeats across the mesh")
        ->check(inRange(0.001, 1000.0));
    cmd->add_option("--mesh", o->mesh,
                    "plane, cube, sphere, cylinder or a mesh file (.obj, .gltf, .glb)")
        ->check(CLI::Validator(
            [](const std::string& name) -> std::string {
                if (parseMeshKind(name) || isMeshFile(name))
                    return {};
                return name + " is neither plane, cube, sphere, cylinder nor a .obj, .gltf or "
                              ".glb file";
            },
            "MESH"));
    cmd->add_option("--uv-set", o->uvSet, "The mesh file's uv set the material uses (default 0)")
        ->check(nonNegative());
    cmd->add_option("--mesh-root", o->meshRoot,
                    "Folder the mesh file's buffers, images and material libraries must lie "
                    "under (default: the mesh's own folder)")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--max-triangles", o->maxTriangles,
                    "Refuse mesh files with more triangles (default 2000000)")
        ->check(positive());
    cmd->add_flag("--derivative-tbn", o->derivativeTbn,
                  "Tangent frame from screen-space derivatives");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT (or one number: square)");
    cmd->add_option("--light", o->light, "Light direction AZIMUTH,ELEVATION in degrees");
    cmd->add_option("--camera", o->camera,
                    "Orbit camera AZIMUTH,ELEVATION,DISTANCE (degrees, world units)");
    cmd->add_option("--background", o->background,
                    "Background R,G,B,A in [0,1] as stored (default transparent), or environment "
                    "(the --environment behind the mesh)");
    cmd->add_option("--environment", o->environment,
                    "Image-based light: an equirectangular .hdr or .exr, or sky (built in)");
    cmd->add_option("--exposure", o->exposure, "Exposure in stops (EV) under --environment")
        ->check(inRange(-20.0, 20.0));
    cmd->add_option("--time", o->timeFrames,
                    "Also time this many frames with each kernel flavour and print the medians "
                    "and their ratio")
        ->check(inRange(1, 10000));
    cmd->add_option("--turntable", o->turntable,
                    "Render this many frames with the camera orbiting once: OUT-000.png, ...")
        ->check(inRange(1, 3600));
    o->kernels.addTo(*cmd);
    o->cache.addTo(*cmd);
    cmd->add_option("--out", o->out, "Output image (.png)")->required();
    return [o] { return runRender(*o); };
}

} // namespace px::cli

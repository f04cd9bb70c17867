// parallax-cli shader: the specialised shader of a material or a feature set, or every variant.

#include "Cli.h"
#include "CommonOptions.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/StagedSet.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/MaterialNames.h"
#include "parallax/shader/ShaderGenerator.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

namespace px::cli {

namespace {

struct ShaderOptions {
    std::string material;
    std::string technique = "pom";
    bool shadow = false;
    bool normalMap = false;
    std::string normalSource;
    bool albedo = false;
    bool orm = false;
    std::string wrap = "repeat";
    std::string lighting = "blinn-phong";
    bool derivativeTbn = false;
    std::string output = "color";
    std::string stage = "fragment";
    std::string out;
    bool list = false;
    std::string dumpAll;
    KernelOptions kernels;
};

Result<VariantKey> keyFrom(const ShaderOptions& o) {
    const ShaderOutput output = o.output == "trace"     ? ShaderOutput::Trace
                                : o.output == "surface" ? ShaderOutput::Surface
                                                        : ShaderOutput::Color;
    if (!o.material.empty()) {
        Result<Material> material = loadMaterial(o.material);
        if (!material)
            return material.error();
        VariantKey k = variantFor(*material, output);
        k.flavour = o.kernels.flavour();
        return canonical(k);
    }
    VariantKey k;
    k.technique = *parseTechnique(o.technique);
    k.shadow = o.shadow;
    k.normalSource = o.normalMap ? NormalSource::Map : NormalSource::HeightCentral;
    if (!o.normalSource.empty())
        k.normalSource = *parseNormalSourceShortName(o.normalSource);
    k.albedoMap = o.albedo;
    k.surfaceMap = o.orm;
    k.wrap = *parseWrapMode(o.wrap);
    k.lighting = *parseLightingModel(o.lighting);
    k.tbn = o.derivativeTbn ? TbnSource::Derivatives : TbnSource::VertexTangents;
    k.output = output;
    k.flavour = o.kernels.flavour();
    if (Status s = k.validate(); !s)
        return s.error();
    return canonical(k);
}

// Each variant's fragment stage as VARIANT.frag; the vertex stages, shared by many variants (they
// read only which outputs the fragment stage keeps), once each as VERTEX-KEY.vert. Every file or
// none: they are staged, then renamed into the folder (StagedSet.h).
int dumpAll(const std::string& dir) {
    std::filesystem::path into = std::filesystem::path(dir).lexically_normal();
    if (into.filename().empty())
        into = into.parent_path();
    std::error_code ec;
    if (!into.parent_path().empty())
        std::filesystem::create_directories(into.parent_path(), ec);
    if (ec)
        return fail(dir + ": cannot create the folder (" + ec.message() + ")");
    Result<StagedSet> stage = StagedSet::begin(into, into.filename().string());
    if (!stage)
        return fail(stage.error().message);
    auto write = [&](const std::string& name, const std::string& text) {
        Status s = writeTextFile(stage->pathFor(name), text);
        if (!s) // named as the user will see it, not the stage
            return fail((into / name).string() + ": " +
                        s.error().message.substr(s.error().message.find(": ") + 2));
        return 0;
    };
    StagedSet::Update update;
    std::set<std::string> vertexStages;
    for (const VariantKey& key : allVariants()) {
        Result<GeneratedProgram> program = generateProgram(key);
        if (!program)
            return fail(key.name() + ": " + program.error().message);
        update.moves.push_back(key.name() + ".frag");
        if (write(update.moves.back(), program->fragment.text) != 0)
            return 1;
        const std::string vertex = program->vertexKey.name();
        if (vertexStages.insert(vertex).second) {
            update.moves.push_back(vertex + ".vert");
            if (write(update.moves.back(), program->vertex.text) != 0)
                return 1;
        }
    }
    if (Status s = stage->commit(update); !s)
        return fail(s.error().message);
    const std::size_t count = update.moves.size() - vertexStages.size();
    std::cout << "wrote " << count << " variants: " << count << " fragment and "
              << vertexStages.size() << " vertex shaders to " << dir << "\n";
    return 0;
}

int runShader(const ShaderOptions& o) {
    if (o.list) {
        for (const VariantKey& key : allVariants())
            std::cout << key.name() << "\n";
        return 0;
    }
    if (!o.dumpAll.empty())
        return dumpAll(o.dumpAll);
    if (o.out.empty())
        return fail("--out is required (or --list, or --dump-all DIR)");
    Result<VariantKey> key = keyFrom(o);
    if (!key)
        return fail(key.error().message);
    Result<GeneratedProgram> program = generateProgram(*key);
    if (!program)
        return fail(program.error().message);
    const std::string& text = o.stage == "vertex" ? program->vertex.text : program->fragment.text;
    if (o.out == "-") {
        std::cout << text;
        return 0;
    }
    if (Status s = writeTextFile(o.out, text); !s)
        return fail(s.error().message);
    return 0;
}

} // namespace

Action addShaderCommand(CLI::App& app) {
    auto o = std::make_shared<ShaderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "shader",
        "Write the shader specialised for a material or a feature set (or every variant)");
    auto* material = cmd->add_option("--material", o->material, "Material file (.json)");
    std::vector<std::string> techniques;
    for (const TechniqueInfo& t : allTechniques())
        techniques.emplace_back(t.name);
    std::vector<CLI::Option*> features{
        cmd->add_option("--technique", o->technique, "Technique (default pom)")
            ->check(CLI::IsMember(techniques)),
        cmd->add_flag("--shadow", o->shadow, "Soft self-shadowing towards the light"),
        cmd->add_flag("--normal-map", o->normalMap, "Shading normals from a normal map"),
        cmd->add_option("--normal-source", o->normalSource,
                        "Shading normals: none, map, central (4 taps of height), sobel (8 taps)")
            ->check(CLI::IsMember(choices(normalSourceShortNames()))),
        cmd->add_flag("--albedo", o->albedo, "An albedo map"),
        cmd->add_flag("--orm", o->orm, "An occlusion/roughness/metallic map"),
        cmd->add_option("--wrap", o->wrap, "Wrap mode")->check(CLI::IsMember({"repeat", "clamp"})),
        cmd->add_option("--lighting", o->lighting, "Lighting model")
            ->check(CLI::IsMember(choices(lightingModelNames()))),
        cmd->add_flag("--derivative-tbn", o->derivativeTbn,
                      "Tangent frame from screen-space derivatives (meshes without tangents)"),
    };
    for (CLI::Option* f : features)
        material->excludes(f);
    cmd->add_option("--output", o->output,
                    "What the shader writes: color, surface (u, v, t, fetches per pixel) or trace "
                    "(the canonical trace scene)")
        ->check(CLI::IsMember({"color", "surface", "trace"}));
    o->kernels.addTo(*cmd);
    cmd->add_option("--stage", o->stage, "Which stage to write")
        ->check(CLI::IsMember({"fragment", "vertex"}));
    cmd->add_option("--out", o->out, "Output file (.frag/.vert); - for standard output");
    cmd->add_flag("--list", o->list, "List every variant's name");
    // Every variant, whatever a material says: a --material beside it would be read for nothing
    // and its maps, never recorded as inputs, could be among the files written.
    cmd->add_option("--dump-all", o->dumpAll,
                    "Write every variant's fragment stage and each distinct vertex stage into "
                    "this folder")
        ->excludes(material);
    return [o] { return runShader(*o); };
}

} // namespace px::cli

// Godot 4: a StandardMaterial3D resource (.tres) with its textures beside it. Texture paths are
// relative to the .tres, which Godot resolves against the resource's own folder, so the folder can
// be dropped anywhere in a project.

#include "ExportJob.h"
#include "ExportTextures.h"
#include "io/ShortestDecimal.h"
#include "parallax/material/SurfaceFactors.h"

#include <sstream>

namespace px::exporter {

namespace {

// Floats as Godot writes them: always with a decimal point ("5.0").
std::string real(double value) {
    std::ostringstream text;
    text << value;
    std::string s = text.str();
    if (s.find_first_of(".e") == std::string::npos)
        s += ".0";
    return s;
}

// Godot's POM offsets by view_dir.xy * heightmap_scale * 0.01 (material.cpp), in uv units.
float godotHeightScale(float s) {
    return s * 100.0f;
}

// The ranges of BaseMaterial3D's inspector (heightmap_scale -16..16, layers 1..64).
constexpr float kGodotScaleSlider = 16.0f;
constexpr int kGodotLayersSlider = 64;

} // namespace

Status writeGodot(ExportJob& job) {
    const Material& m = job.material;
    struct Texture {
        std::string name;
        std::string id;
    };
    std::vector<Texture> textures;
    std::ostringstream props;
    auto texture = [&](const std::string& name, const char* role) {
        textures.push_back({name, std::to_string(textures.size() + 1) + "_" + role});
        return "ExtResource(\"" + textures.back().id + "\")";
    };

    props << "resource_name = \"" << job.stem << "\"\n";
    if (!job.assets.albedo.empty()) {
        const std::string name = job.stem + "_albedo.png";
        if (Status s = job.image(name, job.assets.albedo, PixelFormat::UInt8, true); !s)
            return s;
        props << "albedo_texture = " << texture(name, "albedo") << "\n";
    }
    // Number x texel: the map where there is one, the number where there is not (SurfaceFactors.h).
    const std::optional<Image> orm = job.orm(ExportJob::MissingChannel::One);
    const SurfaceFactors factors =
        surfaceFactors(m, !job.assets.roughness.empty(), !job.assets.metallic.empty());
    props << "metallic = " << real(shortestDecimal(factors.metallic)) << "\n"
          << "roughness = " << real(shortestDecimal(factors.roughness)) << "\n";
    if (orm) {
        const std::string name = job.stem + "_orm.png";
        if (Status s = job.image(name, *orm, PixelFormat::UInt8); !s)
            return s;
        const std::string ref = texture(name, "orm");
        // Texture channels: 0 red, 1 green, 2 blue (BaseMaterial3D::TextureChannel).
        props << "metallic_texture = " << ref << "\nmetallic_texture_channel = 2\n"
              << "roughness_texture = " << ref << "\nroughness_texture_channel = 1\n";
        if (!job.assets.ao.empty()) {
            props << "ao_enabled = true\nao_texture = " << ref << "\nao_texture_channel = 0\n";
            job.noteOcclusion("R of " + name + " (ao_texture, channel red)");
        }
    }
    const std::string normalName = job.stem + "_normal.png";
    Result<bool> normals = job.writeNormals(normalName, NormalGreen::OpenGL);
    if (!normals)
        return normals.error();
    if (*normals)
        props << "normal_enabled = true\nnormal_texture = " << texture(normalName, "normal")
              << "\n";
    const TechniqueInfo& t = info(m.technique);
    if (t.parallax) {
        // A depth map (as the artist's file was) goes out as one, with Godot told to flip it.
        const bool depth = m.heightIsDepth;
        const std::string name = job.heightName(job.stem + (depth ? "_depth" : "_height"));
        if (Status s =
                job.image(name, heightImage(job.assets.height, depth), job.options.heightFormat);
            !s)
            return s;
        // Godot marches layers (deep parallax) or offsets once; it has no cone or pyramid
        // stepping, so those techniques go out as a layer march with the default range.
        const bool deep = m.technique != Technique::Offset || job.engineLayers;
        TraceParams layers = t.usesLayers ? m.params : info(Technique::Pom).defaults;
        if (job.engineLayers) { // technique auto: what Godot's own march needs
            const EngineLayersAdvice& a = *job.engineLayers;
            layers.minLayers = a.found ? a.layers.minLayers : a.tried.minLayers;
            layers.maxLayers = a.found ? a.layers.maxLayers : a.tried.maxLayers;
            job.result.notes.push_back(a.note);
        }
        props << "heightmap_enabled = true\n"
              << "heightmap_scale = " << real(shortestDecimal(godotHeightScale(m.heightScale)))
              << "\n"
              << "heightmap_deep_parallax = " << (deep ? "true" : "false") << "\n";
        if (deep)
            props << "heightmap_min_layers = " << layers.minLayers << "\n"
                  << "heightmap_max_layers = " << layers.maxLayers << "\n";
        props << "heightmap_flip_texture = " << (depth ? "true" : "false") << "\n"
              << "heightmap_texture = " << texture(name, "height") << "\n";
        if (!t.usesLayers && deep && !job.engineLayers)
            job.result.notes.push_back("Godot has no " + std::string(t.name) +
                                       " technique: exported as deep parallax with " +
                                       std::to_string(layers.minLayers) + " to " +
                                       std::to_string(layers.maxLayers) + " layers");
        // Godot offsets by the normalised view vector (sin θ) where the material's relief
        // needs tan θ: the apparent depth is cos θ of the material's.
        job.result.notes.push_back(
            "Godot offsets by sin θ of the view angle, not tan θ: heightmap_scale = " +
            formatDecimal(godotHeightScale(m.heightScale)) +
            " matches the material looking straight down; the relief looks shallower towards "
            "grazing angles (cos θ of its depth: half at 60°)");
        const float scale = godotHeightScale(m.heightScale);
        if (scale > kGodotScaleSlider || (deep && layers.maxLayers > kGodotLayersSlider))
            job.result.notes.push_back(
                "Godot's inspector sliders stop at heightmap_scale " +
                std::to_string(static_cast<int>(kGodotScaleSlider)) + " and " +
                std::to_string(kGodotLayersSlider) +
                " layers: the .tres keeps the exported values, but moving the slider clamps them");
    }
    if (m.selfShadow)
        job.result.notes.push_back("self-shadowing is not exported: Godot's StandardMaterial3D "
                                   "has no parallax self-shadow");
    if (!job.assets.specular.empty())
        job.result.notes.push_back("specular map not exported: Godot's StandardMaterial3D has a "
                                   "specular value (metallic_specular), no specular texture");
    props << "uv1_scale = Vector3(" << real(shortestDecimal(m.tiling)) << ", "
          << real(shortestDecimal(m.tiling)) << ", 1.0)\n"
          << "texture_repeat = " << (m.wrap == WrapMode::Repeat ? "true" : "false") << "\n";

    std::ostringstream tres;
    tres << "[gd_resource type=\"StandardMaterial3D\" load_steps=" << textures.size() + 1
         << " format=3]\n\n";
    for (const Texture& tex : textures)
        tres << "[ext_resource type=\"Texture2D\" path=\"" << tex.name << "\" id=\"" << tex.id
             << "\"]\n";
    tres << (textures.empty() ? "" : "\n") << "[resource]\n" << props.str();
    return job.text(job.stem + ".tres", tres.str());
}

} // namespace px::exporter

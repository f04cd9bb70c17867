// Unreal and Unity: textures named, encoded and channel-packed the way each engine's importer
// and standard materials expect, and a note of the settings to enter (neither has a text
// material format to write).

#include "ExportJob.h"
#include "ExportTextures.h"
#include "io/ShortestDecimal.h"
#include "parallax/material/MapContent.h"

#include <sstream>

namespace px::exporter {

namespace {

// The layer counts in the engine's terms (a technique without layers gets the march defaults).
void stepLines(std::ostringstream& note, const Material& m, const char* minName,
               const char* maxName) {
    const TechniqueInfo& t = info(m.technique);
    const TraceParams layers = t.usesLayers ? m.params : info(Technique::Pom).defaults;
    note << "  " << minName << " = " << layers.minLayers << ", " << maxName << " = "
         << layers.maxLayers << "\n";
    if (!t.usesLayers)
        note << "  (the material uses '" << t.name
             << "', which the engine does not have: these are the layer-march defaults)\n";
}

// The parallax part of the notes: what the material asks for in the engine's terms.
void parallaxLines(std::ostringstream& note, const Material& m, const char* scaleName,
                   const char* minName, const char* maxName) {
    note << "  " << scaleName << " = " << shortestDecimal(m.heightScale)
         << "   (the relief's depth in uv units: h = 0 lies this far below the surface)\n";
    stepLines(note, m, minName, maxName);
}

const char* wrapText(const Material& m) {
    return m.wrap == WrapMode::Repeat ? "Wrap (repeat)" : "Clamp";
}

} // namespace

Status writeUnreal(ExportJob& job) {
    const Material& m = job.material;
    const std::string base = "T_" + job.stem;
    std::ostringstream note;
    note << "Unreal Engine import settings for " << m.name << "\n\nTextures:\n";
    if (!job.assets.albedo.empty()) {
        if (Status s = job.image(base + "_BC.png", job.assets.albedo, PixelFormat::UInt8, true); !s)
            return s;
        note << "  " << base << "_BC.png    Base Color: sRGB on, Compression Default\n";
    }
    Result<bool> normals = job.writeNormals(base + "_N.png", NormalGreen::DirectX);
    if (!normals)
        return normals.error();
    if (*normals) {
        note << "  " << base << "_N.png     Normal: DirectX green (Y-) as Unreal expects; "
             << "Compression Normalmap, sRGB off, Flip Green Channel off\n";
    }
    // Unreal's material reads the texel as the value: a missing map's channel holds the number.
    if (const std::optional<Image> orm = job.orm(ExportJob::MissingChannel::Number)) {
        if (Status s = job.image(base + "_ORM.png", *orm, PixelFormat::UInt8); !s)
            return s;
        note << "  " << base << "_ORM.png   R = Ambient Occlusion, G = Roughness, B = Metallic: "
             << "Compression Masks, sRGB off\n";
        job.noteOcclusion("R of " + base + "_ORM.png (Ambient Occlusion)");
    }
    const bool specular = !job.assets.specular.empty();
    const bool tinted =
        specular && job.assets.specular.channels >= 3 && !imageTraits(job.assets.specular).grey;
    if (specular) {
        if (Status s =
                job.image(base + "_S.png", specularLevel(job.assets.specular), PixelFormat::UInt8);
            !s)
            return s;
        note << "  " << base << "_S.png     Specular level (white = full): Compression Masks, "
             << "sRGB off\n";
        job.result.notes.push_back(
            std::string("specular map written as ") + base +
            "_S for Unreal's Specular input, times 0.5 (Unreal's default 0.5 is the map's white)" +
            (tinted ? "; its tint is dropped (the input is one value: the strongest channel)"
                    : ""));
    }
    const bool parallax = info(m.technique).parallax;
    if (parallax) {
        if (Status s = job.image(job.heightName(base + "_H"), heightImage(job.assets.height, false),
                                 job.options.heightFormat);
            !s)
            return s;
        note << "  " << job.heightName(base + "_H")
             << "     Height (white = high): Compression Grayscale (HDR for .exr), sRGB off\n";
    }
    note << "\nEvery texture: Address X/Y = " << wrapText(m) << ".\n";
    note << "\nMaterial graph:\n";
    if (parallax) {
        note << "  Add the ParallaxOcclusionMapping function; Heightmap Texture = " << base
             << "_H, Heightmap Channel = (1, 0, 0, 0), UVs = TexCoord[0] * "
             << shortestDecimal(m.tiling)
             << ",\n  Reference Plane so that white lies on the surface (the relief is carved "
                "into the polygon), and\n";
        parallaxLines(note, m, "Height Ratio", "Min Steps", "Max Steps");
        note << "  (Unreal does not publish the function's step formula, so these counts are not "
                "measured against its march: check them at the steepest view)\n";
        note << "  Feed its Parallax UVs to every texture sample below.\n";
        if (m.selfShadow)
            note << "  Self-shadowing (on in the material) is not set up: the function's Shadow "
                    "output, with the light vector in tangent space, is where Unreal has it.\n";
    } else {
        note << "  UVs = TexCoord[0] * " << shortestDecimal(m.tiling) << " (no parallax: technique "
             << info(m.technique).name << ").\n";
    }
    if (!job.assets.albedo.empty())
        note << "  Base Color <- " << base << "_BC RGB\n";
    if (*normals)
        note << "  Normal <- " << base << "_N RGB\n";
    if (job.orm(ExportJob::MissingChannel::Number))
        note << "  Ambient Occlusion <- " << base << "_ORM R, Roughness <- G, Metallic <- B\n";
    else
        note << "  Roughness = " << shortestDecimal(m.roughness)
             << ", Metallic = " << shortestDecimal(m.metallic) << "\n";
    if (specular)
        note << "  Specular <- " << base
             << "_S R x 0.5 (a Multiply node: the default 4% reflectance is the map's white)"
             << (tinted ? "; the file's tint is dropped, Specular is one value" : "") << "\n";
    return job.text(job.stem + "_Unreal.txt", note.str());
}

Status writeUnity(ExportJob& job) {
    const Material& m = job.material;
    const std::string base = job.stem;
    std::ostringstream note;
    note << "Unity import settings for " << m.name << "\n\nTextures:\n";
    if (!job.assets.albedo.empty()) {
        if (Status s = job.image(base + "_Albedo.png", job.assets.albedo, PixelFormat::UInt8, true);
            !s)
            return s;
        note << "  " << base << "_Albedo.png              Default, sRGB (Color Texture) on\n";
    }
    Result<bool> normals = job.writeNormals(base + "_Normal.png", NormalGreen::OpenGL);
    if (!normals)
        return normals.error();
    if (*normals) {
        note << "  " << base << "_Normal.png              Texture Type: Normal map (OpenGL green, "
             << "Y+, as Unity expects)\n";
    }
    const bool packed =
        !job.assets.roughness.empty() || !job.assets.metallic.empty() || !job.assets.ao.empty();
    if (packed) {
        // Built-in Standard and URP Lit: metallic in R, smoothness (1 - roughness) in alpha.
        const ChannelSource ms[4] = {{&job.assets.metallic, 0, false, m.metallic},
                                     {&job.assets.metallic, 0, false, m.metallic},
                                     {&job.assets.metallic, 0, false, m.metallic},
                                     {&job.assets.roughness, 0, true, 1.0f - m.roughness}};
        // HDRP Lit mask map: R metallic, G occlusion, B detail mask, A smoothness.
        const ChannelSource mask[4] = {{&job.assets.metallic, 0, false, m.metallic},
                                       {&job.assets.ao, 0, false, 1.0f},
                                       {nullptr, 0, false, 1.0f},
                                       {&job.assets.roughness, 0, true, 1.0f - m.roughness}};
        if (Status s = job.image(base + "_MetallicSmoothness.png", *packChannels(ms, 4, m.wrap),
                                 PixelFormat::UInt8);
            !s)
            return s;
        if (Status s = job.image(base + "_MaskMap.png", *packChannels(mask, 4, m.wrap),
                                 PixelFormat::UInt8);
            !s)
            return s;
        note << "  " << base << "_MetallicSmoothness.png  sRGB off; R = Metallic, A = Smoothness "
             << "(Built-in Standard, URP Lit)\n"
             << "  " << base << "_MaskMap.png             sRGB off; R = Metallic, G = Occlusion, "
             << "B = Detail Mask, A = Smoothness (HDRP Lit)\n";
        if (!job.assets.ao.empty()) {
            if (Status s = job.image(base + "_Occlusion.png", job.assets.ao, PixelFormat::UInt8);
                !s)
                return s;
            note << "  " << base << "_Occlusion.png           sRGB off (Built-in Standard, URP)\n";
            job.noteOcclusion("G of " + base + "_MaskMap.png (HDRP Lit) and " + base +
                              "_Occlusion.png (Built-in Standard, URP Lit)");
        }
    }
    const bool parallax = info(m.technique).parallax;
    if (parallax) {
        if (Status s = job.image(job.heightName(base + "_Height"),
                                 heightImage(job.assets.height, false), job.options.heightFormat);
            !s)
            return s;
        note << "  " << job.heightName(base + "_Height")
             << "              sRGB off, white = high\n";
    }
    if (!job.assets.specular.empty()) {
        const char* why = "Unity's metallic shaders (Standard, URP and HDRP Lit) have no specular "
                          "level map; its specular maps belong to the Specular workflow, where the "
                          "map is the F0 colour in place of metallic";
        note << "  (the material's specular map is not exported: " << why << ")\n";
        job.result.notes.push_back(std::string("specular map not exported: ") + why);
    }
    note << "\nEvery texture: Wrap Mode = " << (m.wrap == WrapMode::Repeat ? "Repeat" : "Clamp")
         << ". Material Tiling = (" << shortestDecimal(m.tiling) << ", "
         << shortestDecimal(m.tiling) << ").\n";
    if (!packed)
        note << "Metallic = " << shortestDecimal(m.metallic)
             << ", Smoothness = " << shortestDecimal(1.0f - m.roughness) << "\n";
    if (parallax) {
        note << "\nHDRP Lit (parallax occlusion): Displacement Mode = Pixel displacement, Height "
                "Map = "
             << job.heightName(base + "_Height")
             << ", Parametrization = Amplitude,\n  Amplitude = " << shortestDecimal(m.heightScale)
             << " x the tile's size in centimetres (" << shortestDecimal(m.heightScale * 100.0f)
             << " cm for a 1 m tile), Base = 1 (white lies on the surface),\n"
             << "  Primitive Length = Primitive Width = the tile's size in metres (1 for a 1 m "
                "tile), Lock with height map tiling rate on:\n  HDRP divides the Amplitude by "
                "the primitive size to get the depth in uv units, so both must match the mesh,\n";
        if (job.engineLayers) { // technique auto: what HDRP's own march needs
            const EngineLayersAdvice& a = *job.engineLayers;
            const EngineLayers& steps = a.found ? a.layers : a.tried;
            note << "  Minimum Steps = " << steps.minLayers
                 << ", Maximum Steps = " << steps.maxLayers << "   (" << a.note << ")\n";
            job.result.notes.push_back(a.note);
        } else {
            stepLines(note, m, "Minimum Steps", "Maximum Steps");
        }
        if (m.selfShadow)
            note << "  Self-shadowing (on in the material) is not exported: HDRP's pixel "
                    "displacement has no self-shadow term (Depth Offset only moves depth).\n";
        note << "Built-in Standard / URP Lit (offset parallax only): Height Map = "
             << job.heightName(base + "_Height")
             << ", Height Scale = " << shortestDecimal(m.heightScale);
        if (m.heightScale < 0.005f || m.heightScale > 0.08f)
            note << " (outside Unity's 0.005 to 0.08 slider: type it in, or expect a different "
                    "depth)";
        note << "\n";
    }
    return job.text(job.stem + "_Unity.txt", note.str());
}

} // namespace px::exporter

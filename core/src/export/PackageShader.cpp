// The package's shaders: the renderer's own program for this material's variant (the generator
// keeps only the code, samplers and uniforms the variant reads), and how to bind it.

#include "ExportJob.h"
#include "ExportTextures.h"
#include "parallax/shader/ShaderGenerator.h"

#include <sstream>

namespace px::exporter {

namespace {

const char* unitContents(int unit) {
    switch (unit) {
    case TextureUnit::Height:
        return "the height map as R16 (or R32F for .exr), mipmapped; never 8-bit";
    case TextureUnit::Cone:
        return "the cone map as RG32F (R height, G sqrt(cone ratio))";
    case TextureUnit::MaxMip:
        return "the max-mip pyramid atlas, R32F, built from the height map when loading "
               "(MaxMipPyramid::atlas())";
    case TextureUnit::Albedo:
        return "the albedo map uploaded as sRGB (GL_SRGB8_ALPHA8: decoded on sampling)";
    case TextureUnit::Normal:
        return "the normal map, linear RGB, OpenGL green (Y+)";
    case TextureUnit::Orm:
        return "occlusion (R), roughness (G), metallic (B), linear";
    default:
        return "";
    }
}

void listUniforms(std::ostringstream& note, const GeneratedShader& shader) {
    for (const ShaderUniform& u : shader.uniforms) {
        note << "  " << u.type << " " << u.name;
        if (u.unit >= 0)
            note << "  (binding " << u.unit << ": " << unitContents(u.unit) << ")";
        note << "\n";
    }
}

} // namespace

Result<std::string> writePackageShader(ExportJob& job, const Material& packaged,
                                       std::vector<std::pair<std::string, std::string>>& files) {
    VariantKey key = variantFor(packaged);
    Result<GeneratedProgram> program = generateProgram(key);
    if (!program)
        return Error{"cannot generate the material's shader: " + program.error().message};
    key = program->key; // canonical
    const std::string frag = job.stem + ".frag";
    const std::string vert = job.stem + ".vert";
    if (Status s = job.text(frag, program->fragment.text); !s)
        return s.error();
    if (Status s = job.text(vert, program->vertex.text); !s)
        return s.error();
    files.emplace_back(frag, "GLSL 4.30 fragment shader of variant " + key.name());
    files.emplace_back(vert, "its vertex shader");

    // The renderer packs occlusion, roughness and metallic into one texture: ship it packed.
    if (key.surfaceMap) {
        const Material& m = job.material;
        const ChannelSource sources[3] = {{&job.assets.ao, 0, false, 1.0f},
                                          {&job.assets.roughness, 0, false, m.roughness},
                                          {&job.assets.metallic, 0, false, m.metallic}};
        if (std::optional<Image> orm = packChannels(sources, 3, m.wrap)) {
            const std::string name = job.stem + "_orm.png";
            if (Status s = job.image(name, *orm, PixelFormat::UInt8); !s)
                return s.error();
            files.emplace_back(name, "occlusion, roughness, metallic packed for the shader");
        }
    }

    std::ostringstream note;
    note << "\nShaders\n\n"
         << frag << " and " << vert << " are the renderer's own program for this material (variant "
         << key.name() << "), with only the code, samplers and uniforms it uses. Defines on:";
    for (const std::string& define : program->fragment.defines)
        note << " " << define;
    note << "\nVertex attributes: location 0 position, 1 normal, 2 uv, 3 tangent (dP/du), "
            "4 bitangent (dP/dv).\n\nFragment uniforms:\n";
    listUniforms(note, program->fragment);
    note << "Vertex uniforms:\n";
    listUniforms(note, program->vertex);
    note << "Set each uniform from the material file (" << job.stem
         << ".json): the height scale, layers, steps and wrap are its values.\n";
    return note.str();
}

} // namespace px::exporter

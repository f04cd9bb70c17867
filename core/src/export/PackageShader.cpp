// The package's shaders: the renderer's own program for this material's variant (the generator
// keeps only the code, samplers and uniforms the variant reads), and how to bind it.

#include "ExportJob.h"
#include "ExportTextures.h"
#include "PackageUniforms.h"
#include "parallax/material/MaterialNames.h"
#include "parallax/shader/ShaderGenerator.h"

#include <cmath>
#include <map>
#include <sstream>

namespace px::exporter {

namespace {

// "  float pxScale = 0.05   must set: height scale s ..." and the binding's format for samplers.
void listUniforms(std::ostringstream& note, const GeneratedShader& shader, const Material& m,
                  float heightMax, const std::map<int, std::string>& unitFiles) {
    for (const ShaderUniform& u : shader.uniforms) {
        note << "  " << u.type << " " << u.name;
        if (u.unit >= 0) {
            const auto file = unitFiles.find(u.unit);
            note << "  binding " << u.unit << ": "
                 << (file != unitFiles.end() ? file->second + " as " : std::string())
                 << unitFormat(u.unit) << "\n";
            continue;
        }
        const UniformValue v = uniformValue(u.name, m, heightMax);
        if (v.meaning.empty()) {
            note << "\n";
            continue;
        }
        note << " = " << v.value << "  (" << (v.mustSet ? "must set" : "default safe") << ": "
             << v.meaning << ")\n";
    }
}

// The largest height as the GPU will see it: the 16-bit file rounds it to the nearest step.
float uploadedHeightMax(const ExportJob& job) {
    const float top = job.assets.height.maxHeight();
    if (job.options.heightFormat == PixelFormat::UInt16)
        return std::round(top * 65535.0f) / 65535.0f;
    return top;
}

} // namespace

Result<std::string> writePackageShader(ExportJob& job, const Material& packaged,
                                       std::vector<std::pair<std::string, std::string>>& files) {
    VariantKey key = variantFor(packaged);
    Result<GeneratedProgram> program = generateProgram(key);
    if (!program)
        return program.error().prefixed("cannot generate the material's shader: ");
    key = program->key; // canonical
    const std::string frag = job.stem + ".frag";
    const std::string vert = job.stem + ".vert";
    if (Status s = job.text(frag, program->fragment.text); !s)
        return s.error();
    if (Status s = job.text(vert, program->vertex.text); !s)
        return s.error();
    files.emplace_back(frag, "GLSL 4.30 fragment shader of variant " + key.name());
    files.emplace_back(vert, "its vertex shader");

    std::map<int, std::string> unitFiles = {
        {TextureUnit::Height, packaged.maps.height},
        {TextureUnit::Cone,
         key.technique == Technique::RelaxedCone ? packaged.maps.relaxedCone : packaged.maps.cone},
        {TextureUnit::Albedo, packaged.maps.albedo},
        {TextureUnit::Normal, packaged.maps.normal}};
    // The renderer packs occlusion, roughness and metallic into one texture: ship it packed.
    // Absent channels hold 1, as in the renderer's: the shader multiplies them by pxRoughness and
    // pxMetallic (a missing metallic map packed as the material's 0.3 drew metallic 0.09).
    if (key.surfaceMap) {
        if (std::optional<Image> orm = job.orm(ExportJob::MissingChannel::One)) {
            const std::string name = job.stem + "_orm.png";
            if (Status s = job.image(name, *orm, PixelFormat::UInt8); !s)
                return s.error();
            files.emplace_back(name, "occlusion, roughness, metallic packed for the shader");
            unitFiles[TextureUnit::Orm] = name;
        }
    }

    std::ostringstream note;
    note << "\nShaders\n\n"
         << frag << " and " << vert << " are the renderer's own program for this material (variant "
         << key.name() << "), with only the code, samplers and uniforms it uses. Defines on:";
    for (const std::string& define : program->fragment.defines)
        note << " " << define;
    note << "\nVertex attributes: location 0 position, 1 normal, 2 uv, 3 tangent (dP/du), "
            "4 bitangent (dP/dv).\n\nFragment uniforms (type name = value; \"must set\": a GL "
            "default of 0 draws it wrong):\n";
    const float heightMax = uploadedHeightMax(job);
    std::erase_if(unitFiles, [](const auto& entry) { return entry.second.empty(); });
    listUniforms(note, program->fragment, packaged, heightMax, unitFiles);
    note << "Vertex uniforms:\n";
    listUniforms(note, program->vertex, packaged, heightMax, unitFiles);
    note << "Every texture: wrap "
         << (packaged.wrap == WrapMode::Repeat ? "GL_REPEAT" : "GL_CLAMP_TO_EDGE")
         << " (the material's " << toString(packaged.wrap) << ").\n";
    note << "Output: pxFragColor is already sRGB-encoded: draw into a plain RGBA8 target with "
            "GL_FRAMEBUFFER_SRGB off (an sRGB target would encode it twice).\n"
         << "The values above are those of " << job.stem
         << ".json; the renderer's own preview uses the same.\n";
    return note.str();
}

} // namespace px::exporter

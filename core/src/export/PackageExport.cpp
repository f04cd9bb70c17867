// The project's own package: the material JSON, the maps its technique reads at the chosen bit
// depth, the specialised fragment shader and a usage note.

#include "ExportJob.h"
#include "ExportTextures.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/MaterialNames.h"

#include <sstream>

namespace px::exporter {

namespace {

std::string describeFormat(PixelFormat format) {
    switch (format) {
    case PixelFormat::UInt8:
        return "8-bit";
    case PixelFormat::UInt16:
        return "16-bit";
    case PixelFormat::Half:
        return "half float";
    case PixelFormat::Float:
        return "float";
    }
    return "";
}

std::string usageNote(const ExportJob& job, const Material& out,
                      const std::vector<std::pair<std::string, std::string>>& files) {
    const TechniqueInfo& t = info(out.technique);
    std::ostringstream note;
    note << out.name << ": a Parallax Studio material package\n\n"
         << "Technique: " << t.name << " (" << t.title << ")";
    if (t.usesLayers)
        note << ", " << out.params.minLayers << " to " << out.params.maxLayers << " layers";
    if (t.usesBinarySteps)
        note << ", " << out.params.binarySteps << " binary steps";
    if (t.usesSecantSteps)
        note << ", " << out.params.secantSteps << " secant steps";
    if (t.usesMaxSteps)
        note << ", at most " << out.params.maxSteps << " steps";
    note << ".\nHeight scale " << out.heightScale << " (uv units: depth of h = 0), wrap "
         << toString(out.wrap) << ", tiling " << out.tiling << ", normals "
         << toString(out.normalSource) << ", lighting " << toString(out.lighting)
         << (out.selfShadow ? ", self-shadowing" : "") << ".\n\nFiles:\n";
    for (const auto& [name, what] : files)
        note << "  " << name << std::string(name.size() < 28 ? 28 - name.size() : 1, ' ') << what
             << "\n";
    note << "\nOpen it with `parallax-studio " << job.stem << ".json` or render it headless with\n"
         << "`parallax-cli render --material " << job.stem << ".json --out preview.png`.\n\n"
         << "Conventions: uv (0, 0) is the top-left texel, v grows down the image; height is\n"
         << "white = high and the relief lies inside the polygon, s (1 - h) below it; normal maps\n"
         << "store n * 0.5 + 0.5, linear, green "
         << (out.normalGreen == NormalGreen::OpenGL ? "up (OpenGL, Y+)" : "down (DirectX, Y-)")
         << ". Cone maps: R = height, G = sqrt(cone ratio), rounded down.\n";
    return note.str();
}

} // namespace

Status writePackage(ExportJob& job) {
    const Material& m = job.material;
    const MapSet used = mapsUsed(m);
    Material out = m; // the package's own material: same settings, its own map files
    out.surface = {}; // occlusion, roughness and metallic are written one map a file
    out.maps = {};
    out.heightChannel = HeightChannel::Red;
    out.heightIsDepth = false; // the height map is written white = high
    out.heightRange.reset();   // ... and from 0 to 1
    out.normalGreen = job.options.packageGreen;
    std::vector<std::pair<std::string, std::string>> files;
    auto add = [&](const std::string& name, const std::string& what) {
        files.emplace_back(name, what);
    };

    if (used.height) {
        const std::string name = job.heightName(job.stem + "_height");
        if (Status s =
                job.image(name, heightImage(job.assets.height, false), job.options.heightFormat);
            !s)
            return s;
        out.maps.height = name;
        add(name, "height, " + describeFormat(job.options.heightFormat) + " linear, white = high");
    }
    if (used.albedo) {
        const std::string name = job.stem + "_albedo.png";
        if (Status s = job.image(name, job.assets.albedo, PixelFormat::UInt8, true); !s)
            return s;
        out.maps.albedo = name;
        add(name, "base colour, 8-bit sRGB");
    }
    if (used.normal) {
        Result<Image> normals = job.normals(job.options.packageGreen);
        if (!normals)
            return normals.error();
        const std::string name = job.stem + "_normal.png";
        if (Status s = job.image(name, *normals, job.options.normalFormat); !s)
            return s;
        out.maps.normal = name;
        add(name, "normal, " + describeFormat(job.options.normalFormat) + " linear, " +
                      (out.normalGreen == NormalGreen::OpenGL ? "OpenGL (Y+)" : "DirectX (Y-)"));
    }
    for (const ConeKind kind : {ConeKind::Conservative, ConeKind::Relaxed}) {
        const bool relaxed = kind == ConeKind::Relaxed;
        if (!(relaxed ? used.relaxedCone : used.cone))
            continue;
        const std::string name = job.stem + (relaxed ? "_relaxed_cone.png" : "_cone.png");
        if (Status s = job.image(name, coneImage(job.assets.height, job.cones(kind), 16),
                                 PixelFormat::UInt16);
            !s)
            return s;
        (relaxed ? out.maps.relaxedCone : out.maps.cone) = name;
        add(name, std::string(relaxed ? "relaxed cone" : "cone") +
                      " map, 16-bit: R = height, G = sqrt(ratio)");
    }
    const std::pair<const Image*, std::string*> linear[] = {
        {&job.assets.ao, &out.maps.ao},
        {&job.assets.roughness, &out.maps.roughness},
        {&job.assets.metallic, &out.maps.metallic}};
    const char* linearNames[] = {"ao", "roughness", "metallic"};
    // Occlusion darkens either lighting model: a baked one goes out as a loaded one would.
    const bool linearUsed[] = {used.ao || !job.occlusionSource.empty(), used.roughness,
                               used.metallic};
    for (int i = 0; i < 3; ++i) {
        if (!linearUsed[i] || linear[i].first->empty())
            continue;
        const std::string name = job.stem + "_" + linearNames[i] + ".png";
        if (Status s = job.image(name, *linear[i].first, PixelFormat::UInt8); !s)
            return s;
        *linear[i].second = name;
        add(name, std::string(linearNames[i]) + ", 8-bit linear");
        if (i == 0)
            job.noteOcclusion(name + " (the package's shader darkens ambient light by it)");
    }

    if (!m.maps.specular.empty())
        job.result.notes.push_back("specular map not in the package: its shader does not read "
                                   "one (the glTF and Unreal exports carry it)");

    const std::string materialName = job.stem + ".json";
    if (Status s = job.text(materialName, materialToJson(out)); !s)
        return s;
    files.insert(files.begin(), {materialName, "the material (format version 1)"});
    Result<std::string> shaderNote = writePackageShader(job, out, files);
    if (!shaderNote)
        return shaderNote.error();
    return job.text("README.txt", usageNote(job, out, files) + *shaderNote);
}

} // namespace px::exporter

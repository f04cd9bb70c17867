// glTF 2.0: one textured plane with a metallic-roughness material. The height parameters (the
// whole Parallax Studio material, maps renamed to the exported files) ride in the material's
// extras, where glTF keeps application data.

#include "ExportJob.h"
#include "ExportTextures.h"
#include "io/ShortestDecimal.h"
#include "parallax/Version.h"
#include "parallax/material/MapContent.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/SurfaceFactors.h"

#include <array>
#include <cctype>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string_view>

namespace px::exporter {

namespace {

using Json = nlohmann::ordered_json;

constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// A 1 m plane in XZ facing +Y; u along +X, v along +Z (v grows down the image, glTF §3.7.2.1),
// so the bitangent cross(N, T) * w = -Z points up the image with w = +1, as glTF's normal maps
// (green up) need.
struct PlaneMesh {
    std::string bytes;
    Json bufferViews = Json::array();
    Json accessors = Json::array();

    template <std::size_t N>
    void add(const std::array<float, N>& values, int components, const char* type,
             bool bounds = false) {
        const std::size_t offset = bytes.size();
        bytes.append(reinterpret_cast<const char*>(values.data()), sizeof(float) * N);
        bufferViews.push_back({{"buffer", 0},
                               {"byteOffset", offset},
                               {"byteLength", sizeof(float) * N},
                               {"target", kArrayBuffer}});
        Json accessor = {{"bufferView", bufferViews.size() - 1},
                         {"componentType", kFloat},
                         {"count", N / components},
                         {"type", type}};
        if (bounds) {
            Json lo = Json::array(), hi = Json::array();
            for (int c = 0; c < components; ++c) {
                float a = values[c], b = values[c];
                for (std::size_t i = c; i < N; i += components) {
                    a = std::min(a, values[i]);
                    b = std::max(b, values[i]);
                }
                lo.push_back(a);
                hi.push_back(b);
            }
            accessor["min"] = lo;
            accessor["max"] = hi;
        }
        accessors.push_back(accessor);
    }

    explicit PlaneMesh(float tiling) {
        add(std::array<float, 12>{-0.5f, 0, -0.5f, 0.5f, 0, -0.5f, 0.5f, 0, 0.5f, -0.5f, 0, 0.5f},
            3, "VEC3", true);
        add(std::array<float, 12>{0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0}, 3, "VEC3");
        add(std::array<float, 16>{1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1}, 4, "VEC4");
        add(std::array<float, 8>{0, 0, tiling, 0, tiling, tiling, 0, tiling}, 2, "VEC2");
        const std::array<unsigned short, 6> indices{0, 2, 1, 0, 3, 2}; // counter-clockwise from +Y
        const std::size_t offset = bytes.size();
        bytes.append(reinterpret_cast<const char*>(indices.data()), sizeof indices);
        bufferViews.push_back({{"buffer", 0},
                               {"byteOffset", offset},
                               {"byteLength", sizeof indices},
                               {"target", kElementArrayBuffer}});
        accessors.push_back({{"bufferView", bufferViews.size() - 1},
                             {"componentType", kUnsignedShort},
                             {"count", indices.size()},
                             {"type", "SCALAR"}});
    }
};

// KHR_materials_specular's texture: a grey map is the strength (read from A), a coloured one the
// F0 colour (RGB, sRGB); RGB holds the file's colour in both, so the texture looks like the map.
Image specularTexture(const Image& specular, bool grey) {
    const Image level = specularLevel(specular);
    Image out(specular.width, specular.height, 4);
    const ImageWriter put = out.writer();
    for (int y = 0; y < specular.height; ++y) {
        for (int x = 0; x < specular.width; ++x) {
            for (int c = 0; c < 3; ++c)
                put.at(x, y, c) = grey ? level.at(x, y, 0) : specular.at(x, y, c);
            put.at(x, y, 3) = grey ? level.at(x, y, 0) : 1.0f;
        }
    }
    return out;
}

// A file name as a glTF URI (RFC 3986): bytes outside the unreserved set percent-encoded, so a
// name of any bytes (an old archive's Latin-1) is a valid URI that loaders decode to the file.
std::string uriOf(const std::string& name) {
    static const char* hex = "0123456789ABCDEF";
    std::string uri;
    for (const char c : name) {
        const auto b = static_cast<unsigned char>(c);
        if (std::isalnum(b) != 0 || std::string_view("-._~").find(c) != std::string_view::npos) {
            uri += c;
        } else {
            uri += '%';
            uri += hex[b >> 4];
            uri += hex[b & 15];
        }
    }
    return uri;
}

} // namespace

Status writeGltf(ExportJob& job) {
    const Material& m = job.material;
    Json images = Json::array(), textures = Json::array();
    auto texture = [&](const std::string& name) {
        images.push_back({{"uri", uriOf(name)}, {"mimeType", "image/png"}});
        textures.push_back({{"sampler", 0}, {"source", images.size() - 1}});
        return Json{{"index", textures.size() - 1}};
    };

    Json pbr = Json::object();
    pbr["baseColorFactor"] = {1.0, 1.0, 1.0, 1.0};
    Json material = {{"name", m.name}};
    if (!job.assets.albedo.empty()) {
        const std::string name = job.stem + "_basecolor.png";
        if (Status s = job.image(name, job.assets.albedo, PixelFormat::UInt8, true); !s)
            return s;
        pbr["baseColorTexture"] = texture(name);
    }
    // Factor x texel: the map where there is one, the number where there is not (SurfaceFactors.h).
    const std::optional<Image> orm = job.orm(ExportJob::MissingChannel::One);
    const SurfaceFactors factors =
        surfaceFactors(m, !job.assets.roughness.empty(), !job.assets.metallic.empty());
    pbr["metallicFactor"] = shortestDecimal(factors.metallic);
    pbr["roughnessFactor"] = shortestDecimal(factors.roughness);
    if (orm) {
        const std::string name = job.stem + "_orm.png";
        if (Status s = job.image(name, *orm, PixelFormat::UInt8); !s)
            return s;
        pbr["metallicRoughnessTexture"] = texture(name);
        if (!job.assets.ao.empty()) { // glTF reads occlusion from R of the same texture
            material["occlusionTexture"] = {{"index", textures.size() - 1}};
            job.noteOcclusion("R of " + name + ", the material's occlusionTexture");
        }
    }
    material["pbrMetallicRoughness"] = pbr;
    const std::string normalName = job.stem + "_normal.png";
    Result<bool> normals = job.writeNormals(normalName, NormalGreen::OpenGL);
    if (!normals)
        return normals.error();
    if (*normals)
        material["normalTexture"] = texture(normalName);

    // The specular map: white is glTF's default reflection (F0 0.04) either way.
    std::string specularName;
    if (!job.assets.specular.empty()) {
        const bool grey = job.assets.specular.channels < 3 || imageTraits(job.assets.specular).grey;
        specularName = job.stem + "_specular.png";
        if (Status s = job.image(specularName, specularTexture(job.assets.specular, grey),
                                 PixelFormat::UInt8, !grey);
            !s)
            return s;
        material["extensions"]["KHR_materials_specular"] = {
            {grey ? "specularTexture" : "specularColorTexture", texture(specularName)}};
        job.result.notes.push_back(
            std::string("specular map written as KHR_materials_specular's ") +
            (grey ? "specularTexture (the strength, in alpha)"
                  : "specularColorTexture (the F0 colour, sRGB)") +
            ": white is glTF's default reflection");
    }

    // The parallax settings: the project's own material, maps renamed to the exported files.
    Material extras = m;
    extras.surface = {}; // the maps below are written one a file, as the material reads them
    extras.maps = {};
    extras.heightChannel = HeightChannel::Red;
    extras.heightIsDepth = false;
    extras.normalGreen = NormalGreen::OpenGL;
    extras.heightRange.reset(); // the height map below is written as 0 to 1
    if (info(m.technique).parallax) {
        const std::string name = job.heightName(job.stem + "_height");
        if (Status s =
                job.image(name, heightImage(job.assets.height, false), job.options.heightFormat);
            !s)
            return s;
        extras.maps.height = name;
    }
    extras.maps.albedo = pbr.contains("baseColorTexture") ? job.stem + "_basecolor.png" : "";
    extras.maps.normal = material.contains("normalTexture") ? job.stem + "_normal.png" : "";
    extras.maps.specular = specularName;
    // The material's own occlusion, roughness and metallic maps, one file each as the material
    // reads them (the packed ORM is glTF's): without them, exporting the extras again would lose
    // them.
    const std::pair<const Image*, std::string*> surface[] = {
        {&job.assets.ao, &extras.maps.ao},
        {&job.assets.roughness, &extras.maps.roughness},
        {&job.assets.metallic, &extras.maps.metallic}};
    const char* surfaceNames[] = {"_ao.png", "_roughness.png", "_metallic.png"};
    for (int i = 0; i < 3; ++i) {
        if (surface[i].first->empty())
            continue;
        const std::string name = job.stem + surfaceNames[i];
        if (Status s = job.image(name, *surface[i].first, PixelFormat::UInt8); !s)
            return s;
        *surface[i].second = name;
    }
    // Normals: the exported normal map when there is one (engines read it, so should the
    // extras); from height only where the height map went out too.
    const bool heightNormals = extras.normalSource == NormalSource::HeightCentral ||
                               extras.normalSource == NormalSource::HeightSobel;
    if (!extras.maps.normal.empty() && extras.maps.height.empty())
        extras.normalSource = NormalSource::Map;
    else if (extras.maps.normal.empty() && (!heightNormals || extras.maps.height.empty()))
        extras.normalSource = NormalSource::None;
    material["extras"] = {{"parallaxStudio", Json::parse(materialToJson(extras))}};

    const PlaneMesh plane(m.tiling);
    const std::string binName = job.stem + ".bin";
    if (Status s = job.text(binName, plane.bytes); !s)
        return s;
    const int wrap = m.wrap == WrapMode::Repeat ? 10497 : 33071;
    Json gltf = {
        {"asset", {{"version", "2.0"}, {"generator", std::string("Parallax Studio ") + kVersion}}},
        {"scene", 0},
        {"scenes", {{{"name", m.name}, {"nodes", {0}}}}},
        {"nodes", {{{"name", m.name}, {"mesh", 0}}}},
        {"meshes",
         {{{"name", m.name + " plane"},
           {"primitives",
            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TANGENT", 2}, {"TEXCOORD_0", 3}}},
              {"indices", 4},
              {"material", 0}}}}}}},
        {"materials", {material}},
        {"buffers", {{{"uri", uriOf(binName)}, {"byteLength", plane.bytes.size()}}}},
        {"bufferViews", plane.bufferViews},
        {"accessors", plane.accessors},
    };
    if (!specularName.empty())
        gltf["extensionsUsed"] = Json::array({"KHR_materials_specular"});
    if (!textures.empty()) {
        gltf["samplers"] = {
            {{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", wrap}, {"wrapT", wrap}}};
        gltf["images"] = images;
        gltf["textures"] = textures;
    }
    // Names are UTF-8 in glTF: bytes that are not are replaced (U+FFFD), never a failed dump.
    return job.text(job.stem + ".gltf",
                    gltf.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
}

} // namespace px::exporter

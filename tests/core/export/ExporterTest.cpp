// Exports: each target gets the maps it needs (and only those) in the encoding it expects, a
// description it can read, and nothing is ever half-written or overwritten without --force.

#include "parallax/export/Exporter.h"

#include "parallax/bake/ConeMapBaker.h"
#include "parallax/export/ExportFolder.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/shader/ShaderGenerator.h"

#include <QTemporaryDir>
#include <QtTest>
#include <nlohmann/json.hpp>

using namespace px;
namespace fs = std::filesystem;

class ExporterTest : public QObject {
    Q_OBJECT

private slots:
    void init();
    void packageHasOnlyTheMapsTheTechniqueNeeds();
    void packageRoundTripsThroughTheLoader();
    void packageFloatHeight();
    void packageDepthMapBecomesHeight();
    void packageBakesMissingConeMapRoundingDown();
    void packageNormalGreenConverted();
    void packagePacksSurfaceMapForTheShader();
    void packedChannelsExportOneMapAFileAndDerivedHeightIsNoted();
    void gltfDescribesPlaneMaterialAndExtras();
    void gltfExtrasAlwaysAValidMaterial();
    void godotMaterialResource();
    void godotNotesWhatItCannotMatch();
    void unrealTexturesAndNote();
    void unityPacking();
    void engineBakesNormalsWithoutANormalMap();
    void neverOverwritesWithoutForce();
    void failedExportLeavesTargetAsItWas();
    void invalidMaterialRefusedBeforeWriting();
    void specularGoesToTheEnginesThatReadIt();
    void floatHeightByItsRangeGoesOutFromZeroToOne();

private:
    std::string path(const std::string& name) const {
        return (fs::path(m_dir->path().toStdString()) / name).string();
    }
    Result<ExportResult> run(ExportFormat format, const std::string& out = "out") {
        m_options.format = format;
        m_options.outDir = path(out);
        return exportMaterial(m_material, m_file, m_options);
    }
    Image read(const std::string& name) {
        Result<Image> image = readImage(path(name));
        if (!image)
            qWarning("%s", image.error().message.c_str());
        return image ? *image : Image{};
    }
    QStringList files(const std::string& folder) const {
        QStringList list;
        for (const auto& e : fs::directory_iterator(path(folder)))
            list << QString::fromStdString(e.path().filename().string());
        list.sort();
        return list;
    }
    void write(const std::string& name, const Image& image, PixelFormat format, bool srgb = false) {
        ImageWriteOptions o;
        o.format = format;
        o.srgb = srgb;
        QVERIFY(writeImage(path(name), image, o).ok());
    }

    std::unique_ptr<QTemporaryDir> m_dir;
    Material m_material;
    std::string m_file;
    ExportOptions m_options;
    HeightField m_height;
};

namespace {

Image constant(int w, int h, std::initializer_list<float> values) {
    Image image(w, h, static_cast<int>(values.size()));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int c = 0;
            for (float v : values)
                image.at(x, y, c++) = v;
        }
    }
    return image;
}

nlohmann::json readJson(const std::string& file) {
    return nlohmann::json::parse(*readTextFile(file));
}

} // namespace

void ExporterTest::init() {
    m_dir.reset(new QTemporaryDir);
    QVERIFY(m_dir->isValid());
    fs::create_directories(path("src"));
    write("src/bricks_height.png", makeProceduralMap(ProceduralMap::Bricks, 32, 16).toImage(),
          PixelFormat::UInt16);
    m_height = *loadHeightField(path("src/bricks_height.png")); // as the exports read it
    write("src/bricks_albedo.png", constant(32, 16, {0.8f, 0.4f, 0.2f}), PixelFormat::UInt8, true);
    // A DirectX (Y-) normal map tilted up the image: green below half.
    write("src/bricks_normal.png", constant(32, 16, {0.5f, 0.25f, 0.9f}), PixelFormat::UInt8);
    write("src/bricks_roughness.png", constant(16, 8, {0.3f}), PixelFormat::UInt8);
    write("src/bricks_ao.png", constant(32, 16, {0.6f}), PixelFormat::UInt8);
    m_material = Material();
    m_material.name = "bricks";
    m_material.maps.height = "bricks_height.png";
    m_material.maps.albedo = "bricks_albedo.png";
    m_material.maps.normal = "bricks_normal.png";
    m_material.maps.roughness = "bricks_roughness.png";
    m_material.normalGreen = NormalGreen::DirectX;
    m_file = path("src/bricks.json");
    m_options = ExportOptions();
}

void ExporterTest::packageHasOnlyTheMapsTheTechniqueNeeds() {
    // pom, normals from height, Blinn-Phong: the normal and roughness files are not read.
    Result<ExportResult> result = run(ExportFormat::Package);
    QVERIFY2(result.ok(), result.ok() ? "" : result.error().message.c_str());
    QCOMPARE(files("out"),
             (QStringList{".parallax-export", "README.txt", "bricks.frag", "bricks.json",
                          "bricks.vert", "bricks_albedo.png", "bricks_height.png"}));
    // The renderer's own program for the variant, and the note says how to bind it.
    Result<GeneratedProgram> program =
        generateProgram(variantFor(*loadMaterial(path("out/bricks.json"))));
    QVERIFY(program.ok());
    QCOMPARE(*readTextFile(path("out/bricks.frag")), program->fragment.text);
    QVERIFY(program->fragment.text.find("pxConeMap") == std::string::npos);
    const std::string note = *readTextFile(path("out/README.txt"));
    QVERIFY2(note.find("Technique: pom (Parallax occlusion mapping), 8 to 32 layers") !=
                 std::string::npos,
             note.c_str());
    QVERIFY(note.find("bricks_height.png") != std::string::npos);
    QVERIFY2(note.find("sampler2D pxHeightMap  binding 0: bricks_height.png as GL_R16 (GL_R32F for "
                       ".exr), mipmapped") != std::string::npos,
             note.c_str());
    // Every value uniform of the shader has its value and meaning in the note, and the values
    // are the material's (the height's maximum as the 16-bit file stores it).
    for (const GeneratedShader* shader : {&program->fragment, &program->vertex}) {
        for (const ShaderUniform& u : shader->uniforms) {
            const std::string line =
                "  " + u.type + " " + u.name + (u.unit >= 0 ? "  binding " : " = ");
            QVERIFY2(note.find(line) != std::string::npos, (u.name + "\n" + note).c_str());
        }
    }
    char heightMax[64];
    std::snprintf(heightMax, sizeof heightMax, "float pxHeightMax = %g  (must set",
                  std::round(m_height.maxHeight() * 65535.0f) / 65535.0f);
    QVERIFY2(note.find(heightMax) != std::string::npos, (heightMax + ("\n" + note)).c_str());
    QVERIFY(note.find("float pxScale = 0.05  (must set") != std::string::npos);
    QVERIFY(note.find("pxFragColor is already sRGB-encoded") != std::string::npos);
    // Albedo stays sRGB 8-bit, height 16-bit.
    const Image albedo = read("out/bricks_albedo.png");
    QVERIFY(std::abs(albedo.at(3, 3, 0) - 0.8f) < 0.5f / 255);
}

void ExporterTest::packageRoundTripsThroughTheLoader() {
    m_material.technique = Technique::Relief;
    m_material.params.binarySteps = 9;
    m_material.normalSource = NormalSource::Map;
    QVERIFY(run(ExportFormat::Package).ok());
    Result<Material> loaded = loadMaterial(path("out/bricks.json"));
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
    QVERIFY(loaded->technique == Technique::Relief);
    QCOMPARE(loaded->params.binarySteps, 9);
    QCOMPARE(QString::fromStdString(loaded->maps.normal), QString("bricks_normal.png"));
    Result<MaterialAssets> assets =
        loadMaterialAssets(*loaded, path("out/bricks.json"), mapsUsed(*loaded));
    QVERIFY2(assets.ok(), assets.ok() ? "" : assets.error().message.c_str());
    double worst = 0;
    for (std::size_t i = 0; i < m_height.texels.size(); ++i)
        worst = std::max(worst, double(std::abs(assets->height.texels[i] - m_height.texels[i])));
    QVERIFY2(worst < 1e-7, qPrintable(QString::number(worst))); // 16-bit kept
}

void ExporterTest::packageFloatHeight() {
    HeightField fine(8, 8);
    for (std::size_t i = 0; i < fine.texels.size(); ++i)
        fine.texels[i] = static_cast<float>(i) / 1000.0f + 1e-6f;
    write("src/fine.exr", fine.toImage(), PixelFormat::Float);
    m_material.maps.height = "fine.exr";
    m_options.heightFormat = PixelFormat::Float;
    QVERIFY(run(ExportFormat::Package).ok());
    const Image height = read("out/bricks_height.exr");
    QCOMPARE(height.pixels, fine.texels); // float end to end
}

void ExporterTest::packageDepthMapBecomesHeight() {
    m_material.heightIsDepth = true;
    QVERIFY(run(ExportFormat::Package).ok());
    const Image height = read("out/bricks_height.png");
    QVERIFY(std::abs(height.at(5, 7) - (1.0f - m_height.at(5, 7))) < 1.0f / 65535);
    Result<Material> loaded = loadMaterial(path("out/bricks.json"));
    QVERIFY(loaded.ok() && !loaded->heightIsDepth);
}

void ExporterTest::packageBakesMissingConeMapRoundingDown() {
    m_material.technique = Technique::Cone;
    m_material.params = info(Technique::Cone).defaults;
    Result<ExportResult> result = run(ExportFormat::Package);
    QVERIFY(result.ok());
    QVERIFY(files("out").contains("bricks_cone.png"));
    QVERIFY(!files("out").contains("bricks_relaxed_cone.png"));
    QVERIFY(!result->notes.empty() && result->notes[0].find("cone map baked") != std::string::npos);
    const ConeMap baked = bakeConeMap(m_height, WrapMode::Repeat, ConeKind::Conservative);
    const Image cone = read("out/bricks_cone.png");
    for (int y = 0; y < m_height.height; ++y) {
        for (int x = 0; x < m_height.width; ++x) {
            QVERIFY(cone.at(x, y, 1) <= baked.g(x, y)); // never wider than baked
            QVERIFY(cone.at(x, y, 1) > baked.g(x, y) - 1.0f / 65535);
            QVERIFY(std::abs(cone.at(x, y, 0) - m_height.at(x, y)) < 1.0f / 65535);
        }
    }
    // The packaged material loads with its cone map (R is checked against the height map).
    Result<Material> loaded = loadMaterial(path("out/bricks.json"));
    QVERIFY(loaded.ok());
    QVERIFY(loadMaterialAssets(*loaded, path("out/bricks.json"), mapsUsed(*loaded)).ok());
}

void ExporterTest::packageNormalGreenConverted() {
    m_material.normalSource = NormalSource::Map;
    QVERIFY(run(ExportFormat::Package, "gl").ok());
    QVERIFY(std::abs(read("gl/bricks_normal.png").at(0, 0, 1) - (1.0f - 0.25f)) < 1.0f / 255);
    m_options.packageGreen = NormalGreen::DirectX;
    QVERIFY(run(ExportFormat::Package, "dx").ok());
    QVERIFY(std::abs(read("dx/bricks_normal.png").at(0, 0, 1) - 0.25f) < 1.0f / 255);
    Result<Material> loaded = loadMaterial(path("dx/bricks.json"));
    QVERIFY(loaded.ok() && loaded->normalGreen == NormalGreen::DirectX);
}

void ExporterTest::packagePacksSurfaceMapForTheShader() {
    m_material.lighting = LightingModel::MetallicRoughness;
    QVERIFY(run(ExportFormat::Package).ok());
    const QStringList written = files("out");
    QVERIFY(written.contains("bricks_roughness.png")); // for the material file
    QVERIFY(written.contains("bricks_orm.png"));       // for the shader's surface map
    QVERIFY(readTextFile(path("out/bricks.frag"))->find("pxOrmMap") != std::string::npos);
    QVERIFY(std::abs(read("out/bricks_orm.png").at(1, 1, 1) - 0.3f) < 1.0f / 255);
}

void ExporterTest::packedChannelsExportOneMapAFileAndDerivedHeightIsNoted() {
    // An imported Unity mask map: roughness = 1 - alpha, occlusion from green.
    write("src/bricks_mask.png", constant(32, 16, {0.2f, 0.5f, 0.8f, 0.3f}), PixelFormat::UInt8);
    m_material.lighting = LightingModel::MetallicRoughness;
    m_material.maps.roughness = m_material.maps.ao = "bricks_mask.png";
    m_material.surface.roughness = HeightChannel::Alpha;
    m_material.surface.gloss = true;
    m_material.surface.ao = HeightChannel::Green;
    m_material.heightDerivedFrom = "bricks_normal.png";
    Result<ExportResult> result = run(ExportFormat::Package);
    QVERIFY2(result, result ? "" : result.error().message.c_str());
    QVERIFY(std::abs(read("out/bricks_roughness.png").at(1, 1) - 0.7f) < 1.0f / 255);
    QVERIFY(std::abs(read("out/bricks_ao.png").at(1, 1) - 0.5f) < 1.0f / 255);
    Result<Material> loaded = loadMaterial(path("out/bricks.json"));
    QVERIFY(loaded && loaded->surface == SurfaceChannels{});
    QCOMPARE(loaded->heightDerivedFrom, std::string("bricks_normal.png"));
    bool noted = false;
    for (const std::string& note : result->notes)
        noted |= note.find("derived from the normal map bricks_normal.png") != std::string::npos;
    QVERIFY(noted);
}

void ExporterTest::gltfDescribesPlaneMaterialAndExtras() {
    m_material.normalSource = NormalSource::Map;
    m_material.lighting = LightingModel::MetallicRoughness;
    m_material.maps.ao = "bricks_ao.png";
    m_material.metallic = 0.25f;
    m_material.tiling = 2.0f;
    QVERIFY(run(ExportFormat::Gltf).ok());
    const nlohmann::json gltf = readJson(path("out/bricks.gltf"));
    QCOMPARE(gltf["asset"]["version"].get<std::string>(), std::string("2.0"));
    const nlohmann::json& material = gltf["materials"][0];
    const nlohmann::json& pbr = material["pbrMetallicRoughness"];
    QVERIFY(pbr.contains("baseColorTexture") && pbr.contains("metallicRoughnessTexture"));
    QCOMPARE(material["occlusionTexture"]["index"], pbr["metallicRoughnessTexture"]["index"]);
    for (const auto& image : gltf["images"])
        QVERIFY(fs::exists(path("out/" + image["uri"].get<std::string>())));
    // Normals in glTF's convention (OpenGL, Y+): the DirectX file's green is flipped.
    QVERIFY(std::abs(read("out/bricks_normal.png").at(1, 1, 1) - 0.75f) < 1.0f / 255);
    // ORM: occlusion in R, roughness in G (resampled from 16x8), no metallic map: 1 in B and the
    // material's metallic as the factor, exactly (SurfaceFactors.h); the roughness map's factor 1.
    const Image orm = read("out/bricks_orm.png");
    QCOMPARE(orm.width, 32);
    QVERIFY(std::abs(orm.at(4, 4, 0) - 0.6f) < 1.0f / 255);
    QVERIFY(std::abs(orm.at(4, 4, 1) - 0.3f) < 1.0f / 255);
    QCOMPARE(orm.at(4, 4, 2), 1.0f);
    QCOMPARE(pbr["metallicFactor"].get<double>(), 0.25);
    QCOMPARE(pbr["roughnessFactor"].get<double>(), 1.0);
    // The height parameters: the material itself, maps renamed to the exported files.
    const nlohmann::json& extras = material["extras"]["parallaxStudio"];
    QCOMPARE(extras["format"].get<std::string>(), std::string("parallax-studio-material"));
    QCOMPARE(extras["height"]["scale"].get<double>(), 0.05);
    QCOMPARE(extras["maps"]["height"].get<std::string>(), std::string("bricks_height.png"));
    QVERIFY(fs::exists(path("out/bricks_height.png")));
    QVERIFY(parseMaterial(extras.dump(), "extras").ok());
    // The extras round-trip: saved beside the glTF they are the whole material (occlusion and
    // roughness maps included), and exporting them again gives the same shader variant.
    QCOMPARE(extras["maps"]["ao"].get<std::string>(), std::string("bricks_ao.png"));
    QCOMPARE(extras["maps"]["roughness"].get<std::string>(), std::string("bricks_roughness.png"));
    QVERIFY(writeTextFile(path("out/extras.json"), extras.dump()).ok());
    Result<Material> again = loadMaterial(path("out/extras.json"));
    QVERIFY2(again.ok(), again.ok() ? "" : again.error().message.c_str());
    QCOMPARE(QString::fromStdString(variantFor(*again).name()),
             QString::fromStdString(variantFor(m_material).name()));
    ExportOptions second;
    second.outDir = path("again");
    Result<ExportResult> repackaged = exportMaterial(*again, path("out/extras.json"), second);
    QVERIFY2(repackaged.ok(), repackaged.ok() ? "" : repackaged.error().message.c_str());
    Result<Material> packaged = loadMaterial(path("again/bricks.json"));
    QVERIFY(packaged.ok());
    QCOMPARE(QString::fromStdString(variantFor(*packaged).name()),
             QString::fromStdString(variantFor(m_material).name()));
    QVERIFY(std::abs(read("again/bricks_orm.png").at(4, 4, 1) - 0.3f) < 1.0f / 255);
    // The plane's uv carry the tiling; the buffer is as long as it says.
    QCOMPARE(gltf["buffers"][0]["byteLength"].get<std::uintmax_t>(),
             fs::file_size(path("out/bricks.bin")));
    QCOMPARE(gltf["samplers"][0]["wrapS"].get<int>(), 10497);
}

void ExporterTest::gltfExtrasAlwaysAValidMaterial() {
    // No parallax: no height map goes out, so the extras take their normals from the normal map.
    m_material.technique = Technique::None;
    QVERIFY(run(ExportFormat::Gltf).ok());
    const nlohmann::json gltf = readJson(path("out/bricks.gltf"));
    const nlohmann::json& extras = gltf["materials"][0]["extras"]["parallaxStudio"];
    QVERIFY(!extras["maps"].contains("height"));
    QCOMPARE(extras["normal"]["source"].get<std::string>(), std::string("map"));
    Result<Material> parsed = parseMaterial(extras.dump(), "extras");
    QVERIFY2(parsed.ok(), parsed.ok() ? "" : parsed.error().message.c_str());
}

void ExporterTest::godotMaterialResource() {
    m_material.heightIsDepth = true;
    m_material.params.minLayers = 12;
    m_material.params.maxLayers = 48;
    m_material.wrap = WrapMode::Clamp;
    QVERIFY(run(ExportFormat::Godot).ok());
    const std::string tres = *readTextFile(path("out/bricks.tres"));
    for (const char* line :
         {"[gd_resource type=\"StandardMaterial3D\" load_steps=5 format=3]",
          "[ext_resource type=\"Texture2D\" path=\"bricks_depth.png\" id=\"4_height\"]",
          "heightmap_enabled = true", "heightmap_scale = 5.0", "heightmap_deep_parallax = true",
          "heightmap_min_layers = 12", "heightmap_max_layers = 48", "heightmap_flip_texture = true",
          "heightmap_texture = ExtResource(\"4_height\")", "normal_enabled = true",
          "roughness_texture_channel = 1", "texture_repeat = false"}) {
        QVERIFY2(tres.find(line) != std::string::npos,
                 qPrintable(QString(line) + "\n" + tres.c_str()));
    }
    // The source was a depth map: it goes out as one (as the file was), with Godot's flip on.
    QVERIFY(std::abs(read("out/bricks_depth.png").at(2, 2) - m_height.at(2, 2)) < 1e-6f);
    QVERIFY(std::abs(read("out/bricks_normal.png").at(0, 0, 1) - 0.75f) < 1.0f / 255);
}

// What Godot cannot do as the material does is said, not dropped: sin θ instead of tan θ, sliders
// that clamp, self-shadowing.
void ExporterTest::godotNotesWhatItCannotMatch() {
    m_material.selfShadow = true;
    m_material.heightScale = 0.2f; // heightmap_scale 20: past the slider's 16
    Result<ExportResult> result = run(ExportFormat::Godot);
    QVERIFY(result.ok());
    const std::string notes = [&] {
        std::string all;
        for (const std::string& n : result->notes)
            all += n + "\n";
        return all;
    }();
    for (const char* text :
         {"Godot offsets by sin θ of the view angle, not tan θ: heightmap_scale "
          "= 20 matches the material looking straight down",
          "half at 60°", "sliders stop at heightmap_scale 16", "self-shadowing is not exported"})
        QVERIFY2(notes.find(text) != std::string::npos,
                 qPrintable(QString(text) + "\n" + notes.c_str()));
    m_material.selfShadow = false;
    m_material.heightScale = 0.05f;
    m_options.force = true;
    result = run(ExportFormat::Godot);
    QVERIFY(result.ok());
    for (const std::string& n : result->notes) {
        QVERIFY2(n.find("sliders") == std::string::npos, n.c_str());
        QVERIFY2(n.find("self-shadowing") == std::string::npos, n.c_str());
    }
}

void ExporterTest::unrealTexturesAndNote() {
    m_material.maps.metallic = "bricks_ao.png"; // any grey map will do
    m_material.maps.ao = "bricks_ao.png";
    QVERIFY(run(ExportFormat::Unreal).ok());
    QCOMPARE(files("out"),
             (QStringList{".parallax-export", "T_bricks_BC.png", "T_bricks_H.png", "T_bricks_N.png",
                          "T_bricks_ORM.png", "bricks_Unreal.txt"}));
    // The DirectX file stays DirectX for Unreal.
    QVERIFY(std::abs(read("out/T_bricks_N.png").at(0, 0, 1) - 0.25f) < 1.0f / 255);
    const Image orm = read("out/T_bricks_ORM.png");
    QVERIFY(std::abs(orm.at(0, 0, 1) - 0.3f) < 1.0f / 255);
    QVERIFY(std::abs(orm.at(0, 0, 2) - 0.6f) < 1.0f / 255);
    const std::string note = *readTextFile(path("out/bricks_Unreal.txt"));
    for (const char* text : {"Height Ratio = 0.05", "Min Steps = 8, Max Steps = 32",
                             "Compression Masks", "Compression Normalmap"})
        QVERIFY2(note.find(text) != std::string::npos, note.c_str());
}

void ExporterTest::unityPacking() {
    QVERIFY(run(ExportFormat::Unity).ok());
    QVERIFY(files("out").contains("bricks_MetallicSmoothness.png"));
    QVERIFY(files("out").contains("bricks_MaskMap.png"));
    QVERIFY(std::abs(read("out/bricks_Normal.png").at(0, 0, 1) - 0.75f) < 1.0f / 255);
    const Image ms = read("out/bricks_MetallicSmoothness.png");
    QCOMPARE(ms.channels, 4);
    QVERIFY(std::abs(ms.at(0, 0, 3) - 0.7f) < 1.0f / 255); // smoothness = 1 - roughness
    QVERIFY(std::abs(ms.at(0, 0, 0) - 0.0f) < 1.0f / 255); // metallic constant
    const std::string note = *readTextFile(path("out/bricks_Unity.txt"));
    QVERIFY2(note.find("Pixel displacement") != std::string::npos, note.c_str());
    QVERIFY2(note.find("Minimum Steps = 8, Maximum Steps = 32") != std::string::npos, note.c_str());
    // HDRP's depth depends on the primitive size: the note names the settings; no stray line.
    QVERIFY2(note.find("Primitive Length = Primitive Width = the tile's size in metres") !=
                 std::string::npos,
             note.c_str());
    QVERIFY2(note.find("Lock with height map tiling rate on") != std::string::npos, note.c_str());
    QVERIFY2(note.find("(height scale)") == std::string::npos, note.c_str());
}

void ExporterTest::engineBakesNormalsWithoutANormalMap() {
    m_material.maps.normal.clear();
    Result<ExportResult> result = run(ExportFormat::Unreal);
    QVERIFY(result.ok());
    QVERIFY(files("out").contains("T_bricks_N.png"));
    bool noted = false;
    for (const std::string& note : result->notes)
        noted |= note.find("normal map baked from the height map") != std::string::npos;
    QVERIFY(noted);
}

void ExporterTest::neverOverwritesWithoutForce() {
    QVERIFY(run(ExportFormat::Package).ok());
    const std::string before = *readTextFile(path("out/bricks.json"));
    m_material.heightScale = 0.1f;
    Result<ExportResult> again = run(ExportFormat::Package);
    QVERIFY(!again.ok());
    QVERIFY(again.error().message.find("use --force") != std::string::npos);
    QCOMPARE(*readTextFile(path("out/bricks.json")), before);
    m_options.force = true;
    QVERIFY(run(ExportFormat::Godot).ok());
    // Nothing is removed: the earlier export's material is kept as it was (and named as kept).
    QCOMPARE(*readTextFile(path("out/bricks.json")), before);
    QVERIFY(fs::exists(path("out/bricks.tres")));
}

void ExporterTest::failedExportLeavesTargetAsItWas() {
    QVERIFY(run(ExportFormat::Package).ok());
    const QStringList before = files("out");
    const QStringList siblings = files("");
    m_options.force = true;
    // Fails while writing (a float normal map cannot go into a PNG), after staging began.
    m_material.normalSource = NormalSource::Map;
    m_options.normalFormat = PixelFormat::Float;
    Result<ExportResult> failed = run(ExportFormat::Package);
    QVERIFY(!failed.ok());
    QVERIFY2(failed.error().message.find("bricks_normal.png") != std::string::npos,
             failed.error().message.c_str());
    QCOMPARE(files("out"), before);
    QCOMPARE(files(""), siblings); // no staging folder left beside it
    // Fails while loading: a missing map is named, and nothing is touched.
    m_options.normalFormat = PixelFormat::UInt8;
    m_material.maps.albedo = "missing.png";
    failed = run(ExportFormat::Package);
    QVERIFY(!failed.ok());
    QCOMPARE(QString::fromStdString(failed.error().message),
             QString::fromStdString(path("src/missing.png") + ": no such file"));
    QCOMPARE(files("out"), before);
}

void ExporterTest::invalidMaterialRefusedBeforeWriting() {
    m_material.params.minLayers = 64;
    m_material.params.maxLayers = 8;
    Result<ExportResult> result = run(ExportFormat::Gltf);
    QVERIFY(!result.ok());
    QVERIFY(result.error().message.find("/technique/minLayers") != std::string::npos);
    QVERIFY(!fs::exists(path("out")));
}

namespace {

bool notes(const ExportResult& result, const std::string& text) {
    return std::any_of(result.notes.begin(), result.notes.end(),
                       [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

} // namespace

// A specular level (grey) and a tinted specular (colour): glTF writes KHR_materials_specular's
// strength or colour texture, Unreal its Specular input at half (its default is 0.5), Godot,
// Unity and the package drop it and say why.
void ExporterTest::specularGoesToTheEnginesThatReadIt() {
    write("src/bricks_spec.png", constant(32, 16, {0.4f}), PixelFormat::UInt8);
    write("src/bricks_tint.png", constant(32, 16, {0.9f, 0.6f, 0.3f}), PixelFormat::UInt8, true);
    for (const bool grey : {true, false}) {
        m_material.maps.specular = grey ? "bricks_spec.png" : "bricks_tint.png";
        m_options.force = true;
        Result<ExportResult> gltf = run(ExportFormat::Gltf, "gltf");
        QVERIFY2(gltf, gltf ? "" : gltf.error().message.c_str());
        const nlohmann::json doc = readJson(path("gltf/bricks.gltf"));
        QCOMPARE(doc["extensionsUsed"], nlohmann::json::array({"KHR_materials_specular"}));
        const nlohmann::json& ext = doc["materials"][0]["extensions"]["KHR_materials_specular"];
        const char* slot = grey ? "specularTexture" : "specularColorTexture";
        QVERIFY2(ext.size() == 1 && ext.contains(slot), ext.dump().c_str());
        const int texture = ext[slot]["index"].get<int>();
        const int source = doc["textures"][texture]["source"].get<int>();
        QCOMPARE(doc["images"][source]["uri"].get<std::string>(),
                 std::string("bricks_specular.png"));
        const Image written = read("gltf/bricks_specular.png");
        QCOMPARE(written.channels, 4);
        QVERIFY(std::abs(written.at(3, 3, 3) - (grey ? 0.4f : 1.0f)) < 1.0f / 255); // strength
        QVERIFY(std::abs(written.at(3, 3, 1) - (grey ? 0.4f : 0.6f)) < 1.0f / 255); // colour
        QCOMPARE(doc["materials"][0]["extras"]["parallaxStudio"]["maps"]["specular"],
                 nlohmann::json("bricks_specular.png"));
        QVERIFY(notes(*gltf, grey ? "specularTexture" : "specularColorTexture"));

        Result<ExportResult> unreal = run(ExportFormat::Unreal, "unreal");
        QVERIFY(unreal);
        const Image level = read("unreal/T_bricks_S.png");
        QCOMPARE(level.channels, 1);
        // The strongest channel (0.9 holds 230/255 in the 8-bit source).
        QVERIFY(std::abs(level.at(2, 2, 0) - (grey ? 0.4f : 0.9f)) < 1.0f / 255);
        const std::string note = *readTextFile(path("unreal/bricks_Unreal.txt"));
        QVERIFY2(note.find("Specular <- T_bricks_S R x 0.5") != std::string::npos, note.c_str());
        QCOMPARE(note.find("tint is dropped") != std::string::npos, !grey);
        QCOMPARE(notes(*unreal, "tint is dropped"), !grey);

        for (const ExportFormat format :
             {ExportFormat::Godot, ExportFormat::Unity, ExportFormat::Package}) {
            const std::string out = "other" + std::to_string(int(format));
            Result<ExportResult> other = run(format, out);
            QVERIFY(other);
            QVERIFY(notes(*other, format == ExportFormat::Package
                                      ? "specular map not in the package"
                                      : "specular map not exported"));
            for (const QString& file : files(out))
                QVERIFY2(!file.contains("spec", Qt::CaseInsensitive), qPrintable(file));
        }
        QVERIFY(!readJson(path("other0/bricks.json"))["maps"].contains("specular"));
    }
    // Without a specular map, no extension and no note.
    m_material.maps.specular.clear();
    Result<ExportResult> plain = run(ExportFormat::Gltf, "plain");
    QVERIFY(plain && !notes(*plain, "specular"));
    const nlohmann::json doc = readJson(path("plain/bricks.gltf"));
    QVERIFY(!doc.contains("extensionsUsed") && !doc["materials"][0].contains("extensions"));
}

// A float height map recorded with its range: every export writes it from 0 to 1, says so, and
// the exported materials (package, glTF extras) carry no range.
void ExporterTest::floatHeightByItsRangeGoesOutFromZeroToOne() {
    Image signedMap = m_height.toImage();
    for (float& v : signedMap.pixels)
        v = -12.5f + 40.0f * v;
    write("src/bricks_bake.exr", signedMap, PixelFormat::Float);
    m_material.maps.height = "bricks_bake.exr";
    HeightRange range{signedMap.pixels[0], signedMap.pixels[0]};
    for (const float v : signedMap.pixels) {
        range.lo = std::min(range.lo, v);
        range.hi = std::max(range.hi, v);
    }
    m_material.heightRange = range;
    for (const ExportFormat format :
         {ExportFormat::Package, ExportFormat::Gltf, ExportFormat::Godot, ExportFormat::Unreal,
          ExportFormat::Unity}) {
        const std::string out = "out" + std::to_string(int(format));
        Result<ExportResult> result = run(format, out);
        QVERIFY2(result, result ? "" : result.error().message.c_str());
        QVERIFY(notes(*result, "are written as 0 to 1"));
        const std::string height = format == ExportFormat::Unreal  ? "T_bricks_H.png"
                                   : format == ExportFormat::Unity ? "bricks_Height.png"
                                                                   : "bricks_height.png";
        const Image written = read(out + "/" + height);
        float worst = 0.0f;
        const float lo = m_height.minHeight(), span = m_height.maxHeight() - lo;
        for (int y = 0; y < written.height; ++y)
            for (int x = 0; x < written.width; ++x)
                worst = std::max(worst,
                                 std::abs(written.at(x, y, 0) - (m_height.at(x, y) - lo) / span));
        QVERIFY2(worst <= 1.0f / 65535 + 1e-5f, qPrintable(QString::number(worst)));
    }
    QVERIFY(!readJson(path("out0/bricks.json"))["height"].contains("range"));
    QVERIFY(
        !readJson(path("out1/bricks.gltf"))["materials"][0]["extras"]["parallaxStudio"]["height"]
             .contains("range"));
}

QTEST_GUILESS_MAIN(ExporterTest)
#include "ExporterTest.moc"

// Occlusion in every export that has a slot for it: a loaded map, or one baked at export when
// asked (ExportOptions::bakeOcclusion). Each target's file is read back texel by texel against
// the map (8-bit: within half a step), the target's description points at the slot, and the notes
// say where the occlusion went.

#include "parallax/bake/OcclusionBaker.h"
#include "parallax/export/Exporter.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QTemporaryDir>
#include <QtTest>
#include <nlohmann/json.hpp>

using namespace px;
namespace fs = std::filesystem;

class ExportOcclusionTest : public QObject {
    Q_OBJECT

private slots:
    void init();
    void loadedOcclusionGoesToEverySlot();
    void bakedOcclusionGoesToEverySlot();
    void noBakeUnlessAsked();
    void aLoadedMapIsNotReplacedByABake();

private:
    std::string path(const std::string& name) const {
        return (fs::path(m_dir->path().toStdString()) / name).string();
    }
    Result<ExportResult> run(ExportFormat format, const std::string& out) {
        m_options.format = format;
        m_options.outDir = path(out);
        return exportMaterial(m_material, path("src/bricks.json"), m_options);
    }
    Image read(const std::string& name) {
        Result<Image> image = readImage(path(name));
        if (!image)
            qWarning("%s", image.error().message.c_str());
        return image ? *image : Image{};
    }
    // Every texel of channel `c` of the file within half an 8-bit step of `expected`.
    void compareChannel(const std::string& file, int c, const Image& expected) {
        const Image got = read(file);
        QCOMPARE(got.width, expected.width);
        QCOMPARE(got.height, expected.height);
        QVERIFY2(got.channels > c, file.c_str());
        for (int y = 0; y < got.height; ++y) {
            for (int x = 0; x < got.width; ++x) {
                const float e = expected.at(x, y, 0), g = got.at(x, y, c);
                QVERIFY2(std::abs(g - e) <= 0.5f / 255 + 1e-6f,
                         qPrintable(QString("%1 channel %2 at (%3, %4): %5, expected %6")
                                        .arg(file.c_str())
                                        .arg(c)
                                        .arg(x)
                                        .arg(y)
                                        .arg(g)
                                        .arg(e)));
            }
        }
    }
    static bool noted(const ExportResult& r, const std::string& text) {
        for (const std::string& note : r.notes) {
            if (note.find(text) != std::string::npos)
                return true;
        }
        qWarning("no note with \"%s\" among:", text.c_str());
        for (const std::string& note : r.notes)
            qWarning("  %s", note.c_str());
        return false;
    }
    // Every target's occlusion slot holds `ao`; the notes name `source`.
    void everySlotHolds(const Image& ao, const std::string& source);

    std::unique_ptr<QTemporaryDir> m_dir;
    Material m_material;
    ExportOptions m_options;
    Image m_ao; // the loaded map: a different value in every texel
};

void ExportOcclusionTest::init() {
    m_dir.reset(new QTemporaryDir);
    QVERIFY(m_dir->isValid());
    fs::create_directories(path("src"));
    ImageWriteOptions sixteen;
    sixteen.format = PixelFormat::UInt16;
    QVERIFY(writeImage(path("src/bricks_height.png"),
                       makeProceduralMap(ProceduralMap::Bricks, 32, 24).toImage(), sixteen)
                .ok());
    m_ao = Image(32, 24, 1);
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 32; ++x)
            m_ao.at(x, y) = static_cast<float>((x * 7 + y * 11) % 256) / 255.0f;
    }
    ImageWriteOptions eight;
    eight.format = PixelFormat::UInt8;
    QVERIFY(writeImage(path("src/bricks_ao.png"), m_ao, eight).ok());
    QVERIFY(writeImage(path("src/bricks_roughness.png"), Image(32, 24, 1), eight).ok());
    m_material = Material();
    m_material.name = "bricks";
    m_material.maps.height = "bricks_height.png";
    m_material.maps.roughness = "bricks_roughness.png";
    m_material.lighting = LightingModel::MetallicRoughness;
    m_material.heightScale = 0.08f;
    m_options = ExportOptions();
}

void ExportOcclusionTest::everySlotHolds(const Image& ao, const std::string& source) {
    const std::string from = "occlusion map (" + source + ") in ";
    // glTF: R of the ORM texture, which the material's occlusionTexture points at.
    Result<ExportResult> gltf = run(ExportFormat::Gltf, "gltf");
    QVERIFY2(gltf.ok(), gltf.ok() ? "" : gltf.error().message.c_str());
    const nlohmann::json doc = nlohmann::json::parse(*readTextFile(path("gltf/bricks.gltf")));
    const int texture = doc["materials"][0]["occlusionTexture"]["index"].get<int>();
    const int image = doc["textures"][texture]["source"].get<int>();
    QCOMPARE(doc["images"][image]["uri"].get<std::string>(), std::string("bricks_orm.png"));
    compareChannel("gltf/bricks_orm.png", 0, ao);
    QVERIFY(noted(*gltf, from + "R of bricks_orm.png, the material's occlusionTexture"));
    // Godot: the ORM's red channel as ao_texture.
    Result<ExportResult> godot = run(ExportFormat::Godot, "godot");
    QVERIFY(godot.ok());
    const std::string tres = *readTextFile(path("godot/bricks.tres"));
    QVERIFY2(tres.find("ao_enabled = true\nao_texture = ExtResource(\"") != std::string::npos &&
                 tres.find("ao_texture_channel = 0\n") != std::string::npos &&
                 tres.find("path=\"bricks_orm.png\"") != std::string::npos,
             tres.c_str());
    compareChannel("godot/bricks_orm.png", 0, ao);
    QVERIFY(noted(*godot, from + "R of bricks_orm.png (ao_texture, channel red)"));
    // Unreal: R of the ORM.
    Result<ExportResult> unreal = run(ExportFormat::Unreal, "unreal");
    QVERIFY(unreal.ok());
    compareChannel("unreal/T_bricks_ORM.png", 0, ao);
    QVERIFY(noted(*unreal, from + "R of T_bricks_ORM.png (Ambient Occlusion)"));
    // Unity: the HDRP mask map's green, and a map of its own for Built-in and URP.
    Result<ExportResult> unity = run(ExportFormat::Unity, "unity");
    QVERIFY(unity.ok());
    compareChannel("unity/bricks_MaskMap.png", 1, ao);
    compareChannel("unity/bricks_Occlusion.png", 0, ao);
    QVERIFY(noted(*unity, from + "G of bricks_MaskMap.png (HDRP Lit) and bricks_Occlusion.png"));
    // The package: a map of its own that its material names (its shader reads it).
    Result<ExportResult> package = run(ExportFormat::Package, "package");
    QVERIFY(package.ok());
    compareChannel("package/bricks_ao.png", 0, ao);
    QCOMPARE(QString::fromStdString(loadMaterial(path("package/bricks.json"))->maps.ao),
             QString("bricks_ao.png"));
    QVERIFY(noted(*package, from + "bricks_ao.png"));
}

void ExportOcclusionTest::loadedOcclusionGoesToEverySlot() {
    m_material.maps.ao = "bricks_ao.png";
    everySlotHolds(m_ao, "bricks_ao.png");
}

// Baked at export: the exact bake of the height map as the export reads it, at the material's
// scale and wrap and the asked distance, in every slot; the note says how it was baked.
void ExportOcclusionTest::bakedOcclusionGoesToEverySlot() {
    m_options.bakeOcclusion = true;
    m_options.occlusionDistance = 0.25;
    m_material.wrap = WrapMode::Clamp;
    OcclusionBakeOptions bake;
    bake.heightScale = m_material.heightScale;
    bake.wrap = WrapMode::Clamp;
    bake.distance = 0.25;
    Result<OcclusionMaps> expected = bakeOcclusion(*loadHeightField(path("src/bricks_height.png")),
                                                   bake, OcclusionOutputs::AmbientOcclusion);
    QVERIFY(expected.ok());
    float darkest = 1.0f;
    for (float v : expected->occlusion.pixels)
        darkest = std::min(darkest, v);
    QVERIFY2(darkest < 0.9f, qPrintable(QString::number(darkest))); // bricks have mortar lines
    everySlotHolds(expected->occlusion, "baked here");
    Result<ExportResult> again = run(ExportFormat::Gltf, "gltf-note");
    QVERIFY(again.ok());
    QVERIFY(noted(*again, "occlusion map baked from the height map (" +
                              std::to_string(kDefaultOcclusionDirections) +
                              " directions, distance 0.25 uv, height scale 0.08, clamp)"));
}

void ExportOcclusionTest::noBakeUnlessAsked() {
    Result<ExportResult> gltf = run(ExportFormat::Gltf, "gltf");
    QVERIFY(gltf.ok());
    const nlohmann::json doc = nlohmann::json::parse(*readTextFile(path("gltf/bricks.gltf")));
    QVERIFY(!doc["materials"][0].contains("occlusionTexture"));
    for (const std::string& note : gltf->notes)
        QVERIFY2(note.find("occlusion map") == std::string::npos, note.c_str());
    const Image orm = read("gltf/bricks_orm.png");
    for (int y = 0; y < orm.height; ++y) {
        for (int x = 0; x < orm.width; ++x)
            QCOMPARE(orm.at(x, y, 0), 1.0f); // no occlusion: white
    }
}

void ExportOcclusionTest::aLoadedMapIsNotReplacedByABake() {
    m_material.maps.ao = "bricks_ao.png";
    m_options.bakeOcclusion = true;
    Result<ExportResult> unreal = run(ExportFormat::Unreal, "unreal");
    QVERIFY(unreal.ok());
    compareChannel("unreal/T_bricks_ORM.png", 0, m_ao);
    QVERIFY(noted(*unreal, "occlusion map (bricks_ao.png) in R of T_bricks_ORM.png"));
    for (const std::string& note : unreal->notes)
        QVERIFY2(note.find("occlusion map baked") == std::string::npos, note.c_str());
}

QTEST_GUILESS_MAIN(ExportOcclusionTest)
#include "ExportOcclusionTest.moc"

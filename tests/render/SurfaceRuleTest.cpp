// One rule for roughness and metallic (parallax/material/SurfaceFactors.h): where a material has
// the map, the map's texel is the value; where it has none, its number is. Checked by rendering
// under the metallic-roughness model: the preview of a material with constant roughness and
// metallic maps against the preview of the same material with no such maps and the rule's values
// as its numbers; and the values each export writes (glTF's factor x texel, Godot's number x
// texel, the package's uniform x texel) drawn the same way. The preview once multiplied a map by
// the number (a metallic map drew no metal at the default metallic 0).

#include "RenderTestSupport.h"
#include "parallax/export/Exporter.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/render/Camera.h"
#include "parallax/render/GpuMaterial.h"
#include "parallax/render/Renderer.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <optional>

using namespace px;

namespace {

constexpr glm::ivec2 kSize{64, 64};

struct Values {
    float roughness = 0.0f;
    float metallic = 0.0f;
};

QString text(const std::string& path) {
    QFile file(QString::fromStdString(path));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

// A channel of the (constant) texture `name` in `folder`.
float texel(const std::string& folder, const std::string& name, int channel) {
    Result<Image> image = readImage(folder + "/" + name);
    if (!image || channel >= image->channels)
        qFatal("%s: unreadable or no channel %d", name.c_str(), channel);
    return image->at(3, 5, channel);
}

// glTF 2.0: roughness = roughnessFactor x G, metallic = metallicFactor x B of the
// metallicRoughnessTexture (factor alone without one).
Values gltfValues(const std::string& folder) {
    const QJsonObject gltf =
        QJsonDocument::fromJson(text(folder + "/untitled.gltf").toUtf8()).object();
    const QJsonObject pbr =
        gltf["materials"].toArray()[0].toObject()["pbrMetallicRoughness"].toObject();
    Values v{static_cast<float>(pbr["roughnessFactor"].toDouble(1.0)),
             static_cast<float>(pbr["metallicFactor"].toDouble(1.0))};
    if (pbr.contains("metallicRoughnessTexture")) {
        const int image =
            gltf["textures"]
                .toArray()[pbr["metallicRoughnessTexture"].toObject()["index"].toInt()]
                .toObject()["source"]
                .toInt();
        const std::string uri =
            gltf["images"].toArray()[image].toObject()["uri"].toString().toStdString();
        v.roughness *= texel(folder, uri, 1);
        v.metallic *= texel(folder, uri, 2);
    }
    return v;
}

// Godot 4's BaseMaterial3D: ROUGHNESS = roughness x the roughness texture's channel, METALLIC
// likewise.
Values godotValues(const std::string& folder) {
    const QString tres = text(folder + "/untitled.tres");
    auto number = [&](const QString& key) {
        const QRegularExpressionMatch m =
            QRegularExpression("\n" + key + " = ([0-9.e-]+)\n").match(tres);
        return m.hasMatch() ? m.captured(1).toFloat() : -1.0f;
    };
    Values v{number("roughness"), number("metallic")};
    const QRegularExpressionMatch file =
        QRegularExpression("path=\"(?:res://)?([^\"]*_orm\\.png)\"").match(tres);
    if (tres.contains("roughness_texture = ")) {
        if (!file.hasMatch())
            qFatal("%s: no packed texture named", qPrintable(tres));
        v.roughness *= texel(folder, file.captured(1).toStdString(),
                             static_cast<int>(number("roughness_texture_channel")));
        v.metallic *= texel(folder, file.captured(1).toStdString(),
                            static_cast<int>(number("metallic_texture_channel")));
    }
    return v;
}

// The package's README: pxRoughness and pxMetallic multiply G and B of its packed texture.
Values packageValues(const std::string& folder) {
    const QString readme = text(folder + "/README.txt");
    auto uniform = [&](const QString& name) {
        const QRegularExpressionMatch m =
            QRegularExpression("float " + name + " = ([0-9.e-]+) ").match(readme);
        return m.hasMatch() ? m.captured(1).toFloat() : -1.0f;
    };
    Values v{uniform("pxRoughness"), uniform("pxMetallic")};
    if (QFile::exists(QString::fromStdString(folder + "/untitled_orm.png"))) {
        v.roughness *= texel(folder, "untitled_orm.png", 1);
        v.metallic *= texel(folder, "untitled_orm.png", 2);
    }
    return v;
}

} // namespace

class SurfaceRuleTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void previewAndExportsDrawOneRule_data();
    void previewAndExportsDrawOneRule();

private:
    Result<Image> render(const MaterialAssets& assets, const Material& m) {
        Result<std::unique_ptr<GpuMaterial>> gpu = GpuMaterial::create(assets, m.wrap);
        if (!gpu)
            return gpu.error();
        OrbitCamera camera;
        camera.elevationDeg = 50.0f;
        camera.distance = 2.0f;
        DirectionalLight light;
        light.azimuthDeg = 210.0f;
        light.elevationDeg = 40.0f;
        return m_renderer->renderImage(**gpu, m, camera, light, {}, kSize);
    }

    std::unique_ptr<Renderer> m_renderer;
};

void SurfaceRuleTest::initTestCase() {
    QVERIFY(test::glContext());
    Result<std::unique_ptr<Renderer>> r = Renderer::create();
    QVERIFY(r.ok());
    m_renderer = std::move(*r);
}

void SurfaceRuleTest::previewAndExportsDrawOneRule_data() {
    QTest::addColumn<float>("roughnessMap"); // < 0: no map
    QTest::addColumn<float>("metallicMap");
    QTest::addColumn<float>("roughness");
    QTest::addColumn<float>("metallic");
    QTest::newRow("metallic map, metallic 0") << -1.0f << 0.9f << 0.6f << 0.0f;
    QTest::newRow("roughness map, roughness 0.6") << 0.25f << -1.0f << 0.6f << 0.3f;
    QTest::newRow("both maps, other numbers") << 0.35f << 0.7f << 0.8f << 0.1f;
    QTest::newRow("no maps") << -1.0f << -1.0f << 0.45f << 0.5f;
}

void SurfaceRuleTest::previewAndExportsDrawOneRule() {
    QFETCH(float, roughnessMap);
    QFETCH(float, metallicMap);
    QFETCH(float, roughness);
    QFETCH(float, metallic);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string folder = dir.path().toStdString();
    auto constantMap = [&](const char* name, float value) {
        Image map(16, 16, 1);
        std::fill(map.pixels.begin(), map.pixels.end(), value);
        QVERIFY(writeImage(folder + "/" + name, map, {}).ok());
    };
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 32, 32, 4);
    Image height(field.width, field.height, 1);
    std::copy(field.texels.begin(), field.texels.end(), height.pixels.begin());
    QVERIFY(writeImage(folder + "/height.png", height, {}).ok());
    Material m = test::sampleMaterial(Technique::Normal);
    m.name = "untitled";
    m.maps = {};
    m.maps.height = "height.png";
    m.lighting = LightingModel::MetallicRoughness;
    m.roughness = roughness;
    m.metallic = metallic;
    if (roughnessMap >= 0.0f) {
        constantMap("roughness.png", roughnessMap);
        m.maps.roughness = "roughness.png";
    }
    if (metallicMap >= 0.0f) {
        constantMap("metallic.png", metallicMap);
        m.maps.metallic = "metallic.png";
    }
    const std::string materialFile = folder + "/material.json";
    QVERIFY(saveMaterial(m, materialFile).ok());
    Result<MaterialAssets> assets = loadMaterialAssets(m, materialFile, mapsUsed(m));
    QVERIFY(assets.ok());

    // The rule, from the maps as loaded (8-bit steps).
    const Values rule{assets->roughness.empty() ? roughness : assets->roughness.at(0, 0),
                      assets->metallic.empty() ? metallic : assets->metallic.at(0, 0)};
    MaterialAssets plain = *assets;
    plain.roughness = {};
    plain.metallic = {};
    auto drawn = [&](Values v) {
        Material numbers = m;
        numbers.maps.roughness.clear();
        numbers.maps.metallic.clear();
        numbers.roughness = v.roughness;
        numbers.metallic = v.metallic;
        return render(plain, numbers);
    };
    Result<Image> expected = drawn(rule);
    Result<Image> preview = render(*assets, m);
    QVERIFY(expected.ok() && preview.ok());
    const test::ImageDifference d = test::compareImages(*preview, *expected, 2);
    QVERIFY2(d.meanAbs < 0.1 && d.maxAbs <= 1,
             qPrintable(QString("preview against the rule: mean %1 steps, max %2")
                            .arg(d.meanAbs)
                            .arg(d.maxAbs)));

    // Each export's own values, drawn: the same picture.
    const std::pair<ExportFormat, Values (*)(const std::string&)> exports[] = {
        {ExportFormat::Gltf, gltfValues},
        {ExportFormat::Godot, godotValues},
        {ExportFormat::Package, packageValues}};
    for (const auto& [format, values] : exports) {
        ExportOptions options;
        options.format = format;
        options.outDir = folder + "/" + std::string(toString(format));
        Result<ExportResult> exported = exportMaterial(m, materialFile, options);
        QVERIFY2(exported.ok(), exported ? "" : exported.error().message.c_str());
        const Values v = values(options.outDir);
        QVERIFY2(std::abs(v.roughness - rule.roughness) < 1e-6f &&
                     std::abs(v.metallic - rule.metallic) < 1e-6f,
                 qPrintable(QString("%1 writes roughness %2, metallic %3; the rule says %4, %5")
                                .arg(toString(format).data())
                                .arg(v.roughness)
                                .arg(v.metallic)
                                .arg(rule.roughness)
                                .arg(rule.metallic)));
        Result<Image> image = drawn(v);
        QVERIFY(image.ok());
        const test::ImageDifference e = test::compareImages(*image, *preview, 2);
        QVERIFY2(e.meanAbs < 0.1, qPrintable(QString("%1 drawn against the preview: mean %2 steps")
                                                 .arg(toString(format).data())
                                                 .arg(e.meanAbs)));
    }
}

QTEST_GUILESS_MAIN(SurfaceRuleTest)
#include "SurfaceRuleTest.moc"

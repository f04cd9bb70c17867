// Loading a material's maps: paths relative to the material file, channel and invert applied,
// only the maps asked for, and every failing map named in the error.

#include "parallax/material/MaterialAssets.h"

#include "parallax/image/ImageFile.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>

using namespace px;

class MaterialAssetsTest : public QObject {
    Q_OBJECT

private slots:
    void init();
    void mapsUsedFollowTheTechnique();
    void heightChannelAndInvert();
    void mapsRelativeToTheMaterialFile();
    void onlyTheMapsAskedFor();
    void everyFailingMapNamed();
    void normalNeedsThreeChannels();
    void missingHeightMap();
    void coneMapLoads();
    void coneMapOfAnotherHeightRefused();
    void coneMapOfAnotherSizeRefused();

private:
    std::string path(const std::string& name) const {
        return m_dir.filePath(QString::fromStdString(name)).toStdString();
    }
    void write(const std::string& name, const Image& image,
               PixelFormat format = PixelFormat::UInt16) {
        ImageWriteOptions options;
        options.format = format;
        std::filesystem::create_directories(std::filesystem::path(path(name)).parent_path());
        const Status s = writeImage(path(name), image, options);
        QVERIFY2(s.ok(), s.ok() ? "" : s.error().message.c_str());
    }
    QTemporaryDir m_dir;
    Material m_material;
    std::string m_file; // the material file's path (it need not exist)
};

namespace {

// Channel c of texel (x, y) holds a distinct value per channel.
Image pattern(int w, int h, int channels) {
    Image image(w, h, channels);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int c = 0; c < channels; ++c)
                image.at(x, y, c) = static_cast<float>((x * 7 + y * 3 + c * 5) % 16) / 15.0f;
        }
    }
    return image;
}

} // namespace

void MaterialAssetsTest::init() {
    QVERIFY(m_dir.isValid());
    m_material = Material();
    m_material.maps.height = "tex/h.png";
    m_material.maps.albedo = "tex/albedo.png";
    m_file = path("mat/m.json");
    std::filesystem::create_directories(path("mat"));
    write("mat/tex/h.png", pattern(8, 4, 3));
    write("mat/tex/albedo.png", pattern(8, 4, 4), PixelFormat::UInt8);
}

void MaterialAssetsTest::mapsUsedFollowTheTechnique() {
    Material m;
    m.maps.height = "h.png";
    MapSet used = mapsUsed(m);
    QVERIFY(used.height && !used.cone && !used.relaxedCone && !used.normal && !used.albedo);
    m.technique = Technique::Cone;
    QVERIFY(mapsUsed(m).cone && !mapsUsed(m).relaxedCone);
    m.technique = Technique::RelaxedCone;
    QVERIFY(mapsUsed(m).relaxedCone && !mapsUsed(m).cone);
    // Normal mapping from a map reads no height at all.
    m.technique = Technique::Normal;
    m.normalSource = NormalSource::Map;
    m.maps.normal = "n.png";
    used = mapsUsed(m);
    QVERIFY(used.normal && !used.height);
    // Roughness only under metallic-roughness, and only when there is a file.
    m.maps.roughness = "r.png";
    QVERIFY(!mapsUsed(m).roughness);
    m.lighting = LightingModel::MetallicRoughness;
    QVERIFY(mapsUsed(m).roughness && !mapsUsed(m).metallic);
}

void MaterialAssetsTest::heightChannelAndInvert() {
    m_material.heightChannel = HeightChannel::Green;
    m_material.heightIsDepth = true;
    MapSet which;
    which.height = true;
    Result<MaterialAssets> assets = loadMaterialAssets(m_material, m_file, which);
    QVERIFY2(assets.ok(), assets.ok() ? "" : assets.error().message.c_str());
    const Image source = pattern(8, 4, 3);
    QCOMPARE(assets->height.width, 8);
    QCOMPARE(assets->height.height, 4);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x)
            QVERIFY(std::abs(assets->height.at(x, y) - (1.0f - source.at(x, y, 1))) < 1e-4f);
    }
}

void MaterialAssetsTest::mapsRelativeToTheMaterialFile() {
    Result<MaterialAssets> assets =
        loadMaterialAssets(m_material, m_file, mapsPresent(m_material.maps));
    QVERIFY2(assets.ok(), assets.ok() ? "" : assets.error().message.c_str());
    QCOMPARE(assets->albedo.channels, 4);
    QCOMPARE(assets->albedo.at(3, 2, 3), pattern(8, 4, 4).at(3, 2, 3));
    QVERIFY(!assets->height.empty());
}

void MaterialAssetsTest::onlyTheMapsAskedFor() {
    MapSet which;
    which.albedo = true;
    Result<MaterialAssets> assets = loadMaterialAssets(m_material, m_file, which);
    QVERIFY(assets.ok());
    QVERIFY(!assets->albedo.empty());
    QVERIFY(assets->height.empty());
    // Asked for but absent from the material: left empty, not an error.
    which.normal = true;
    QVERIFY(loadMaterialAssets(m_material, m_file, which).ok());
}

void MaterialAssetsTest::everyFailingMapNamed() {
    m_material.maps.albedo = "missing_albedo.png";
    m_material.maps.roughness = "missing_rough.png";
    MapSet which = mapsPresent(m_material.maps);
    Result<MaterialAssets> assets = loadMaterialAssets(m_material, m_file, which);
    QVERIFY(!assets.ok());
    const QStringList lines = QString::fromStdString(assets.error().message).split('\n');
    QCOMPARE(lines.size(), 2);
    QCOMPARE(lines[0], QString::fromStdString(path("mat/missing_albedo.png") + ": no such file"));
    QCOMPARE(lines[1], QString::fromStdString(path("mat/missing_rough.png") + ": no such file"));
}

void MaterialAssetsTest::normalNeedsThreeChannels() {
    write("mat/n.png", pattern(8, 4, 2));
    m_material.maps.normal = "n.png";
    MapSet which;
    which.normal = true;
    Result<MaterialAssets> assets = loadMaterialAssets(m_material, m_file, which);
    QVERIFY(!assets.ok());
    QCOMPARE(QString::fromStdString(assets.error().message),
             QString::fromStdString(path("mat/n.png") +
                                    ": a normal map needs at least 3 channels, the file has 2"));
}

void MaterialAssetsTest::missingHeightMap() {
    m_material.maps.height.clear();
    MapSet which;
    which.height = true;
    Result<MaterialAssets> assets = loadMaterialAssets(m_material, m_file, which);
    QVERIFY(!assets.ok());
    QCOMPARE(QString::fromStdString(assets.error().message),
             QString::fromStdString(m_file + ": the material has no height map"));
}

void MaterialAssetsTest::coneMapLoads() {
    const Image h = pattern(8, 4, 1);
    Image cone(8, 4, 2);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x) {
            cone.at(x, y, 0) = h.at(x, y);
            cone.at(x, y, 1) = static_cast<float>(x) / 8.0f;
        }
    }
    write("mat/h1.png", h);
    write("mat/cone.png", cone);
    m_material.maps.height = "h1.png";
    m_material.maps.cone = "cone.png";
    MapSet which;
    which.height = which.cone = true;
    Result<MaterialAssets> assets = loadMaterialAssets(m_material, m_file, which);
    QVERIFY2(assets.ok(), assets.ok() ? "" : assets.error().message.c_str());
    QVERIFY(assets->cone.kind == ConeKind::Conservative);
    QCOMPARE(assets->cone.width, 8);
    QVERIFY(std::abs(assets->cone.g(5, 2) - 5.0f / 8.0f) < 1e-4f);
    QVERIFY(assets->relaxedCone.sqrtRatio.empty());
}

void MaterialAssetsTest::coneMapOfAnotherHeightRefused() {
    Image cone = pattern(8, 4, 2);
    cone.at(6, 1, 0) = 1.0f - cone.at(6, 1, 0) * 0.5f; // R differs from the height map there
    write("mat/cone.png", cone);
    m_material.maps.cone = "cone.png";
    m_material.technique = Technique::Cone;
    MapSet which;
    which.height = which.cone = true;
    Result<MaterialAssets> assets = loadMaterialAssets(m_material, m_file, which);
    QVERIFY(!assets.ok());
    const QString message = QString::fromStdString(assets.error().message);
    QVERIFY2(message.startsWith(QString::fromStdString(path("mat/cone.png"))), qPrintable(message));
    QVERIFY2(message.contains("baked from another height map"), qPrintable(message));
}

void MaterialAssetsTest::coneMapOfAnotherSizeRefused() {
    write("mat/cone.png", pattern(4, 4, 2));
    m_material.maps.relaxedCone = "cone.png";
    MapSet which;
    which.height = which.relaxedCone = true;
    Result<MaterialAssets> assets = loadMaterialAssets(m_material, m_file, which);
    QVERIFY(!assets.ok());
    QCOMPARE(QString::fromStdString(assets.error().message),
             QString::fromStdString(path("mat/cone.png") +
                                    ": the cone map is 4x4 but the height map is 8x4"));
}

QTEST_GUILESS_MAIN(MaterialAssetsTest)
#include "MaterialAssetsTest.moc"

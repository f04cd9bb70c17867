// Golden images on llvmpipe (deterministic: docs/platform.md): every technique on the
// built-in bricks, plus a few feature combinations, 128 x 128. Regenerate after an intended change:
//   PX_UPDATE_GOLDEN=1 ctest -R render.Golden
// and review the new PNGs in tests/render/golden/ before committing them. On a mismatch the
// rendered image is written beside the test binary (golden-actual-NAME.png).

#include "RenderTestSupport.h"
#include "Renderer.h"
#include "parallax/image/ImageFile.h"

#include <QtTest>

using namespace px;

namespace {

struct Case {
    std::string name;
    Material material;
    DrawOptions options;
    OrbitCamera camera;
    DirectionalLight light;
    bool albedo = true;
};

OrbitCamera closeUp() {
    OrbitCamera c;
    c.azimuthDeg = 25.0f;
    c.elevationDeg = 38.0f;
    c.distance = 2.4f;
    return c;
}

std::vector<Case> cases() {
    std::vector<Case> all;
    for (const TechniqueInfo& t : allTechniques()) {
        Case c{std::string(t.name), test::sampleMaterial(t.id), {}, closeUp(), {}, true};
        all.push_back(c);
    }
    {
        Case c{"pom-shadow-clamp-cube", test::sampleMaterial(Technique::Pom), {}, {}, {}, true};
        c.material.selfShadow = true;
        c.material.shadowSoftness = 0.3f;
        c.material.wrap = WrapMode::Clamp;
        c.material.heightScale = 0.1f;
        c.options.mesh = MeshKind::Cube;
        c.camera.distance = 4.2f;
        c.light.azimuthDeg = 60.0f;
        c.light.elevationDeg = 30.0f;
        all.push_back(c);
    }
    {
        Case c{"relief-sobel-metallic-roughness-sphere",
               test::sampleMaterial(Technique::Relief),
               {},
               {},
               {},
               true};
        c.material.normalSource = NormalSource::HeightSobel;
        c.material.lighting = LightingModel::MetallicRoughness;
        c.material.roughness = 0.4f;
        c.material.metallic = 0.2f;
        c.options.mesh = MeshKind::Sphere;
        c.camera.distance = 3.4f;
        all.push_back(c);
    }
    {
        Case c{"cone-derivative-tbn-cylinder",
               test::sampleMaterial(Technique::Cone),
               {},
               {},
               {},
               false};
        c.options.mesh = MeshKind::Cylinder;
        c.options.tbn = TbnSource::Derivatives;
        c.material.tiling = 2.0f;
        c.camera.distance = 3.8f;
        all.push_back(c);
    }
    return all;
}

} // namespace

class GoldenTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void matchesGolden_data();
    void matchesGolden();

private:
    std::unique_ptr<Renderer> m_renderer;
    std::unique_ptr<GpuMaterial> m_withAlbedo, m_plain;
};

void GoldenTest::initTestCase() {
    QVERIFY(test::glContext());
    Result<std::unique_ptr<Renderer>> r = Renderer::create();
    QVERIFY(r.ok());
    m_renderer = std::move(*r);
}

void GoldenTest::matchesGolden_data() {
    QTest::addColumn<int>("index");
    const std::vector<Case> all = cases();
    for (std::size_t i = 0; i < all.size(); ++i)
        QTest::newRow(all[i].name.c_str()) << static_cast<int>(i);
}

void GoldenTest::matchesGolden() {
    QFETCH(int, index);
    const Case c = cases()[static_cast<std::size_t>(index)];
    Result<std::unique_ptr<GpuMaterial>> gpu =
        GpuMaterial::create(test::bricksAssets(128, c.albedo), c.material.wrap);
    QVERIFY(gpu.ok());
    Result<Image> image =
        m_renderer->renderImage(**gpu, c.material, c.camera, c.light, c.options, {128, 128});
    QVERIFY2(image.ok(), image ? "" : image.error().message.c_str());

    const std::string golden = std::string(PX_GOLDEN_DIR) + "/" + c.name + ".png";
    ImageWriteOptions png;
    png.srgb = true;
    if (qEnvironmentVariableIsSet("PX_UPDATE_GOLDEN")) {
        QVERIFY(writeImage(golden, *image, png).ok());
        qInfo("wrote %s", golden.c_str());
        return;
    }
    Result<Image> expected = readImage(golden);
    QVERIFY2(expected.ok(),
             expected ? "" : (expected.error().message + " (PX_UPDATE_GOLDEN=1 makes it)").c_str());
    // llvmpipe is deterministic on one machine; allow rounding-level noise from other CPUs' vector
    // widths, never a visible change.
    const test::ImageDifference d = test::compareImages(*image, *expected, 2);
    const bool ok = d.sameSize && d.meanAbs < 0.25 && d.pixelsOver <= 16;
    if (!ok) {
        const std::string actual =
            QDir::currentPath().toStdString() + "/golden-actual-" + c.name + ".png";
        (void)writeImage(actual, *image, png);
        QFAIL(qPrintable(
            QString("%1 differs from its golden image: mean %2 steps, max %3, %4 pixels over 2 "
                    "steps; the render is in %5")
                .arg(c.name.c_str())
                .arg(d.meanAbs)
                .arg(d.maxAbs)
                .arg(d.pixelsOver)
                .arg(actual.c_str())));
    }
}

QTEST_APPLESS_MAIN(GoldenTest)
#include "GoldenTest.moc"

// Golden images: every technique on the built-in bricks, plus a few feature combinations,
// 128 x 128, made on llvmpipe (deterministic: docs/platform.md). On other renderers the rules of
// GoldenPolicy.h apply: goldens of their own if recorded, else llvmpipe's under a tolerance.
// Regenerate after an intended change:
//   PX_UPDATE_GOLDEN=1 ctest -R render.Golden
// and review the new PNGs in tests/render/golden/ (a GPU writes golden/<renderer key>/) before
// committing them. On a mismatch the rendered image is written beside the test binary
// (golden-actual-NAME.png).

#include "GoldenPolicy.h"
#include "RenderTestSupport.h"
#include "parallax/image/ImageFile.h"
#include "parallax/light/Environment.h"
#include "parallax/light/EnvironmentLighting.h"
#include "parallax/render/Renderer.h"

#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>

using namespace px;

namespace {

struct Case {
    std::string name;
    Material material;
    DrawOptions options;
    OrbitCamera camera;
    DirectionalLight light;
    bool albedo = true;
    bool sky = false; // lit by the built-in environment, shown behind
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
    {
        // The built-in environment on a sphere: image-based light, the sun's soft shadow, the sky
        // behind.
        Case c{"relief-shadow-metallic-roughness-sky-sphere",
               test::sampleMaterial(Technique::Relief),
               {},
               {},
               {},
               true};
        c.material.lighting = LightingModel::MetallicRoughness;
        c.material.roughness = 0.35f;
        c.material.metallic = 0.3f;
        c.material.selfShadow = true;
        c.material.shadowSoftness = 0.3f;
        c.options.mesh = MeshKind::Sphere;
        c.options.showEnvironment = true;
        c.camera.distance = 3.4f;
        c.light.azimuthDeg = 120.0f;
        c.light.elevationDeg = 30.0f;
        c.sky = true;
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
    void rendererKeys_data();
    void rendererKeys();
    void rulesFollowTheRenderer();
    void gpuToleranceCatchesBrokenPictures_data();
    void gpuToleranceCatchesBrokenPictures();
    void gpuToleranceAcceptsRoundingNoise();

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
    Case c = cases()[static_cast<std::size_t>(index)];
    std::unique_ptr<GpuEnvironment> environment;
    if (c.sky) {
        Result<std::unique_ptr<GpuEnvironment>> made = GpuEnvironment::create(
            prefilterEnvironment(makeSkyEnvironment(c.light.direction(), 512)));
        QVERIFY(made.ok());
        environment = std::move(*made);
        c.options.environment = environment.get();
    }
    Result<std::unique_ptr<GpuMaterial>> gpu =
        GpuMaterial::create(test::bricksAssets(128, c.albedo), c.material.wrap);
    QVERIFY(gpu.ok());
    Result<Image> image =
        m_renderer->renderImage(**gpu, c.material, c.camera, c.light, c.options, {128, 128});
    QVERIFY2(image.ok(), image ? "" : image.error().message.c_str());

    const bool updating = qEnvironmentVariableIsSet("PX_UPDATE_GOLDEN");
    const test::GoldenRule rule =
        test::goldenRule(PX_GOLDEN_DIR, c.name, m_renderer->glInfo().renderer, updating);
    ImageWriteOptions png;
    png.srgb = true;
    if (updating) {
        std::filesystem::create_directories(std::filesystem::path(rule.path).parent_path());
        QVERIFY(writeImage(rule.path, *image, png).ok());
        qInfo("wrote %s", rule.path.c_str());
        return;
    }
    qInfo("%s", rule.why.c_str());
    Result<Image> expected = readImage(rule.path);
    QVERIFY2(expected.ok(),
             expected ? "" : (expected.error().message + " (PX_UPDATE_GOLDEN=1 makes it)").c_str());
    const test::ImageDifference d =
        test::compareImages(*image, *expected, rule.tolerance.stepsPerPixel);
    if (!test::withinTolerance(d, rule.tolerance, image->width * image->height)) {
        const std::string actual =
            QDir::currentPath().toStdString() + "/golden-actual-" + c.name + ".png";
        (void)writeImage(actual, *image, png);
        QFAIL(qPrintable(QString("%1 differs from %2: mean %3 steps, max %4, %5 pixels over %6 "
                                 "steps; the render is in %7")
                             .arg(c.name.c_str(), rule.path.c_str())
                             .arg(d.meanAbs)
                             .arg(d.maxAbs)
                             .arg(d.pixelsOver)
                             .arg(rule.tolerance.stepsPerPixel)
                             .arg(actual.c_str())));
    }
}

void GoldenTest::rendererKeys_data() {
    QTest::addColumn<QString>("glRenderer");
    QTest::addColumn<QString>("key");
    QTest::newRow("llvmpipe") << "llvmpipe (LLVM 15.0.6, 256 bits)"
                              << "llvmpipe";
    QTest::newRow("nvidia") << "NVIDIA GeForce RTX 4090/PCIe/SSE2"
                            << "nvidia-geforce-rtx-4090-pcie-sse2";
    QTest::newRow("amd") << "AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54)"
                         << "amd-radeon-rx-7900-xtx-radeonsi-navi31-llvm-15-0-7-drm-3-54";
    QTest::newRow("softpipe is not llvmpipe") << "softpipe"
                                              << "softpipe";
    QTest::newRow("nothing usable") << "///"
                                    << "unknown-renderer";
}

void GoldenTest::rendererKeys() {
    QFETCH(QString, glRenderer);
    QFETCH(QString, key);
    QCOMPARE(QString::fromStdString(test::rendererKey(glRenderer.toStdString())), key);
}

void GoldenTest::rulesFollowTheRenderer() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string root = dir.path().toStdString();
    const std::string gpu = "NVIDIA GeForce RTX 4090/PCIe/SSE2";
    // llvmpipe: the shared goldens, strictly.
    test::GoldenRule r = test::goldenRule(root, "pom", "llvmpipe (LLVM 15.0.6, 256 bits)");
    QCOMPARE(r.path, root + "/pom.png");
    QCOMPARE(r.tolerance.maxMeanSteps, test::kSameRendererTolerance.maxMeanSteps);
    // A GPU with no goldens of its own: llvmpipe's, under the GPU tolerance, and it says so.
    r = test::goldenRule(root, "pom", gpu);
    QCOMPARE(r.path, root + "/pom.png");
    QCOMPARE(r.tolerance.maxMeanSteps, test::kGpuTolerance.maxMeanSteps);
    QVERIFY(r.why.find("no goldens of its own") != std::string::npos);
    // Updating on that GPU writes its own folder, never llvmpipe's goldens.
    r = test::goldenRule(root, "pom", gpu, true);
    QCOMPARE(r.path, root + "/nvidia-geforce-rtx-4090-pcie-sse2/pom.png");
    // Once recorded, its own goldens are used, strictly; other cases still fall back.
    std::filesystem::create_directories(root + "/nvidia-geforce-rtx-4090-pcie-sse2");
    std::ofstream(root + "/nvidia-geforce-rtx-4090-pcie-sse2/pom.png") << "x";
    r = test::goldenRule(root, "pom", gpu);
    QCOMPARE(r.path, root + "/nvidia-geforce-rtx-4090-pcie-sse2/pom.png");
    QCOMPARE(r.tolerance.maxMeanSteps, test::kSameRendererTolerance.maxMeanSteps);
    QCOMPARE(test::goldenRule(root, "relief", gpu).path, root + "/relief.png");
}

// The GPU tolerance still fails a broken picture: llvmpipe's goldens of techniques that a bug
// could swap in, compared with the one expected.
void GoldenTest::gpuToleranceCatchesBrokenPictures_data() {
    QTest::addColumn<QString>("expected");
    QTest::addColumn<QString>("rendered");
    QTest::newRow("no relief (offset for pom)") << "pom"
                                                << "offset";
    QTest::newRow("stair steps (steep for pom)") << "pom"
                                                 << "steep";
    QTest::newRow("flat (normal for offset)") << "offset"
                                              << "normal";
    QTest::newRow("no normals (none for normal)") << "normal"
                                                  << "none";
}

void GoldenTest::gpuToleranceCatchesBrokenPictures() {
    QFETCH(QString, expected);
    QFETCH(QString, rendered);
    Result<Image> a = readImage(std::string(PX_GOLDEN_DIR) + "/" + expected.toStdString() + ".png");
    Result<Image> b = readImage(std::string(PX_GOLDEN_DIR) + "/" + rendered.toStdString() + ".png");
    QVERIFY(a.ok() && b.ok());
    const test::GoldenTolerance& t = test::kGpuTolerance;
    const test::ImageDifference d = test::compareImages(*b, *a, t.stepsPerPixel);
    qInfo("mean %.2f steps, %d pixels over %d", d.meanAbs, d.pixelsOver, t.stepsPerPixel);
    QVERIFY(!test::withinTolerance(d, t, a->width * a->height));
}

// ... and lets through differences of filtering and rounding: a golden with every channel moved
// by up to one step and 1% of its pixels by 40 steps (edges, filtered texels) passes it, though
// it fails the same-renderer rule.
void GoldenTest::gpuToleranceAcceptsRoundingNoise() {
    Result<Image> golden = readImage(std::string(PX_GOLDEN_DIR) + "/relief.png");
    QVERIFY(golden.ok());
    Image noisy = *golden;
    std::uint32_t state = 12345;
    auto next = [&] { return (state = state * 1664525u + 1013904223u) >> 16; }; // high bits
    for (int y = 0; y < noisy.height; ++y) {
        for (int x = 0; x < noisy.width; ++x) {
            const bool edge = next() % 100 == 0;
            for (int c = 0; c < std::min(noisy.channels, 3); ++c) {
                const int step = edge ? 40 : static_cast<int>(next() % 3) - 1;
                float& v = noisy.at(x, y, c);
                v = std::clamp(v + step / 255.0f, 0.0f, 1.0f);
            }
        }
    }
    const int pixels = noisy.width * noisy.height;
    const test::ImageDifference gpu =
        test::compareImages(noisy, *golden, test::kGpuTolerance.stepsPerPixel);
    qInfo("mean %.2f steps, %d pixels over %d", gpu.meanAbs, gpu.pixelsOver,
          test::kGpuTolerance.stepsPerPixel);
    QVERIFY(test::withinTolerance(gpu, test::kGpuTolerance, pixels));
    const test::ImageDifference same =
        test::compareImages(noisy, *golden, test::kSameRendererTolerance.stepsPerPixel);
    QVERIFY(!test::withinTolerance(same, test::kSameRendererTolerance, pixels));
}

QTEST_APPLESS_MAIN(GoldenTest)
#include "GoldenTest.moc"

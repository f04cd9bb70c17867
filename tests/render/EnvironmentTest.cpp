// Image-based light in the renderer: the environment behind the mesh is the map seen through
// each pixel (checked against the CPU's mapping and tone map), a brighter environment brightens
// the mesh, and the sun's self-shadow still darkens the occluded texels under the environment.

#include "parallax/light/Environment.h"

#include "RenderTestSupport.h"
#include "parallax/light/EnvironmentLighting.h"
#include "parallax/render/Renderer.h"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace px;

namespace {

constexpr glm::ivec2 kSize{64, 64};

OrbitCamera view() {
    OrbitCamera c;
    c.azimuthDeg = 20.0f;
    c.elevationDeg = 25.0f;
    c.distance = 3.4f;
    return c;
}

// The tone map and encoding of shaders/render/environment.glsl and lighting.glsl, on the CPU.
glm::vec3 displayed(glm::vec3 radiance, float exposure) {
    const glm::vec3 x = radiance * std::exp2(exposure);
    glm::vec3 c =
        glm::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
    for (int k = 0; k < 3; ++k)
        c[k] = c[k] <= 0.0031308f ? c[k] * 12.92f : 1.055f * std::pow(c[k], 1.0f / 2.4f) - 0.055f;
    return c;
}

double meshLuminance(const Image& image) {
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (image.at(x, y, 3) == 1.0f) {
                sum += image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2);
                ++n;
            }
    return n > 0 ? sum / (3.0 * n) : 0.0;
}

} // namespace

class EnvironmentTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void backgroundIsTheEnvironment();
    void brighterEnvironmentBrightens_data();
    void brighterEnvironmentBrightens();
    void sunShadowStillDarkens();

private:
    std::unique_ptr<GpuEnvironment> environment(const Image& map) {
        Result<std::unique_ptr<GpuEnvironment>> e =
            GpuEnvironment::create(prefilterEnvironment(map, 128, 5));
        return e ? std::move(*e) : nullptr;
    }
    std::unique_ptr<Renderer> m_renderer;
    std::unique_ptr<GpuMaterial> m_bricks;
};

void EnvironmentTest::initTestCase() {
    QVERIFY(test::glContext());
    Result<std::unique_ptr<Renderer>> r = Renderer::create();
    QVERIFY(r.ok());
    m_renderer = std::move(*r);
    Result<std::unique_ptr<GpuMaterial>> gpu =
        GpuMaterial::create(test::bricksAssets(64), WrapMode::Repeat);
    QVERIFY(gpu.ok());
    m_bricks = std::move(*gpu);
}

// Each background pixel shows the map along the ray through its centre (level 0, exposed, tone
// mapped, sRGB) as the CPU computes it; hidden, the background is the clear colour.
void EnvironmentTest::backgroundIsTheEnvironment() {
    DirectionalLight sun;
    const Image sky = makeSkyEnvironment(sun.direction(), 256);
    const PrefilteredEnvironment pre = prefilterEnvironment(sky, 128, 5);
    Result<std::unique_ptr<GpuEnvironment>> env = GpuEnvironment::create(pre);
    QVERIFY(env.ok());
    DrawOptions options;
    options.mesh = MeshKind::Sphere;
    options.environment = env->get();
    options.showEnvironment = true;
    options.exposure = -0.5f;
    const OrbitCamera cam = view();
    Material m = test::sampleMaterial(Technique::Pom);
    Result<Image> shown = m_renderer->renderImage(*m_bricks, m, cam, sun, options, kSize);
    QVERIFY(shown.ok());
    const glm::mat4 inverse = glm::inverse(cam.projection(1.0f) * cam.view());
    int compared = 0;
    float worst = 0.0f;
    for (int y = 0; y < kSize.y; y += 3) {
        for (int x = 0; x < kSize.x; x += 3) {
            const glm::vec2 ndc((x + 0.5f) / kSize.x * 2.0f - 1.0f,
                                1.0f - (y + 0.5f) / kSize.y * 2.0f);
            const glm::vec4 far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 d = glm::vec3(far) / far.w - cam.position();
            // Off the sphere (radius 1): the background.
            const glm::vec3 o = cam.position(), u = glm::normalize(d);
            const float b = glm::dot(o, u), c = glm::dot(o, o) - 1.0f;
            if (b * b - c > -0.05f)
                continue;
            const glm::vec3 expected = displayed(sampleEquirect(pre.specular[0], d), -0.5f);
            for (int k = 0; k < 3; ++k)
                worst = std::max(worst, std::abs(shown->at(x, y, k) - expected[k]));
            QCOMPARE(shown->at(x, y, 3), 1.0f);
            ++compared;
        }
    }
    QVERIFY(compared > 100);
    QVERIFY2(worst < 3.0f / 255.0f, qPrintable(QString("worst %1 steps").arg(worst * 255.0f)));
    options.showEnvironment = false;
    Result<Image> hidden = m_renderer->renderImage(*m_bricks, m, cam, sun, options, kSize);
    QVERIFY(hidden.ok());
    QCOMPARE(hidden->at(0, 0, 3), 0.0f); // the default clear colour: transparent
}

void EnvironmentTest::brighterEnvironmentBrightens_data() {
    QTest::addColumn<int>("lighting");
    QTest::newRow("metallic-roughness") << static_cast<int>(LightingModel::MetallicRoughness);
    QTest::newRow("blinn-phong") << static_cast<int>(LightingModel::BlinnPhong);
}

// The same sky three times as bright (the sun light unchanged): the mesh is brighter overall and
// no pixel is darker.
void EnvironmentTest::brighterEnvironmentBrightens() {
    QFETCH(int, lighting);
    DirectionalLight sun;
    const Image sky = makeSkyEnvironment(sun.direction(), 256);
    std::unique_ptr<GpuEnvironment> dim = environment(sky);
    std::unique_ptr<GpuEnvironment> bright = environment(scaledEnvironment(sky, 3.0f));
    QVERIFY(dim && bright);
    Material m = test::sampleMaterial(Technique::Relief);
    m.lighting = static_cast<LightingModel>(lighting);
    m.roughness = 0.5f;
    DrawOptions options;
    options.mesh = MeshKind::Sphere;
    options.environment = dim.get();
    Result<Image> a = m_renderer->renderImage(*m_bricks, m, view(), sun, options, kSize);
    options.environment = bright.get();
    Result<Image> b = m_renderer->renderImage(*m_bricks, m, view(), sun, options, kSize);
    QVERIFY(a.ok() && b.ok());
    const double la = meshLuminance(*a), lb = meshLuminance(*b);
    QVERIFY2(lb > la * 1.2, qPrintable(QString("%1 -> %2").arg(la).arg(lb)));
    int darker = 0;
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x)
            for (int k = 0; k < 3; ++k)
                darker += b->at(x, y, k) < a->at(x, y, k) - 1.5f / 255.0f;
    QCOMPARE(darker, 0);
}

// A low sun over the bricks, under the sky: with self-shadowing on, the mortar's occluded texels
// lose the sun's light and the picture darkens; the environment still lights them (not black).
void EnvironmentTest::sunShadowStillDarkens() {
    DirectionalLight sun;
    sun.elevationDeg = 20.0f;
    sun.color = glm::vec3(3.0f); // the sun outshines the sky, as outdoors
    std::unique_ptr<GpuEnvironment> env = environment(makeSkyEnvironment(sun.direction(), 256));
    QVERIFY(env);
    Material m = test::sampleMaterial(Technique::Pom);
    m.heightScale = 0.1f;
    m.lighting = LightingModel::MetallicRoughness;
    m.shadowSoftness = 0.2f;
    DrawOptions options;
    options.environment = env.get();
    OrbitCamera cam = view();
    cam.distance = 2.6f;
    Result<Image> lit = m_renderer->renderImage(*m_bricks, m, cam, sun, options, kSize);
    m.selfShadow = true;
    Result<Image> shadowed = m_renderer->renderImage(*m_bricks, m, cam, sun, options, kSize);
    QVERIFY(lit.ok() && shadowed.ok());
    const double l = meshLuminance(*lit), s = meshLuminance(*shadowed);
    qInfo("mean %.3f lit, %.3f shadowed", l, s);
    QVERIFY2(s < 0.97 * l, qPrintable(QString("%1 lit, %2 shadowed").arg(l).arg(s)));
    int brighter = 0, darkened = 0;
    double darkest = 1.0;
    for (int y = 0; y < kSize.y; ++y) {
        for (int x = 0; x < kSize.x; ++x) {
            if (lit->at(x, y, 3) != 1.0f)
                continue;
            brighter += shadowed->at(x, y, 1) > lit->at(x, y, 1) + 1.5f / 255.0f;
            darkened += shadowed->at(x, y, 1) < lit->at(x, y, 1) - 8.0f / 255.0f;
            darkest = std::min(darkest, double(shadowed->at(x, y, 1)));
        }
    }
    qInfo("%d pixels darkened by more than 8 steps, %d brighter", darkened, brighter);
    QCOMPARE(brighter, 0);
    QVERIFY(darkened > kSize.x * kSize.y / 20);
    QVERIFY(darkest > 0.0); // the sky still lights the shadowed texels
}

QTEST_APPLESS_MAIN(EnvironmentTest)
#include "EnvironmentTest.moc"

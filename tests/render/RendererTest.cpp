// The renderer's behaviour: the rendered hits are the CPU's, normal maps and height normals agree,
// the two tangent-frame paths agree, clamp silhouettes, bakes only for what the technique reads,
// 16-bit heights stay 16-bit, uniform changes never recompile, no NaN at grazing views.

#include "parallax/render/Renderer.h"

#include "RenderTestSupport.h"
#include "TestMeshes.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/ConeMapFinish.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"
#include "parallax/mesh/MeshLoader.h"
#include "parallax/render/TextureUpload.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/ParallaxBound.h"
#include "parallax/trace/Tracer.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

using namespace px;

namespace {

constexpr glm::ivec2 kSize{96, 96};

OrbitCamera camera(float azimuth = 25.0f, float elevation = 40.0f, float distance = 2.6f) {
    OrbitCamera c;
    c.azimuthDeg = azimuth;
    c.elevationDeg = elevation;
    c.distance = distance;
    return c;
}

double luminance(const Image& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x)
            sum += image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2);
    }
    return sum / (3.0 * image.width * image.height);
}

int covered(const Image& surface) {
    int n = 0;
    for (int y = 0; y < surface.height; ++y) {
        for (int x = 0; x < surface.width; ++x)
            n += surface.at(x, y, 2) >= 0.0f;
    }
    return n;
}

// A normal map baked from `field` at height scale s the way docs/conventions.md §3 says: central
// differences in uv units, n ∝ (-s dh/du, +s dh/dv, 1), stored n / 2 + 1/2; green flipped for
// DirectX.
Image normalMapOf(const HeightField& field, float s, bool directX) {
    Image image(field.width, field.height, 3);
    auto h = [&](int x, int y) {
        return field.at((x + field.width) % field.width, (y + field.height) % field.height);
    };
    for (int y = 0; y < field.height; ++y) {
        for (int x = 0; x < field.width; ++x) {
            const float du = (h(x + 1, y) - h(x - 1, y)) * 0.5f * field.width;
            const float dv = (h(x, y + 1) - h(x, y - 1)) * 0.5f * field.height;
            glm::vec3 n = glm::normalize(glm::vec3(-s * du, s * dv, 1.0f));
            if (directX)
                n.y = -n.y;
            for (int c = 0; c < 3; ++c)
                image.at(x, y, c) = n[c] * 0.5f + 0.5f;
        }
    }
    return image;
}

} // namespace

class RendererTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void renderedHitsAreTheCpuTracersHits_data();
    void renderedHitsAreTheCpuTracersHits();
    void renderedHitsOnLoadedMeshes_data();
    void renderedHitsOnLoadedMeshes();
    void normalMapAndHeightNormalsAgree();
    void derivativeFrameMatchesVertexFrame();
    void clampDiscardsRaysLeavingTheTile();
    void bakesOnlyWhatTheTechniqueReads();
    void mapsUploadAs16BitWhereTheyFit();
    void bigMapsUploadInBandsExactly();
    void aNewMaterialKeepsTheTexturesOfUnchangedMaps();
    void uniformChangesDoNotRecompile();
    void grazingViewsStayFinite();
    void shadowsDarkenOnlyWhereTheLightIsLow();
    void everyMeshDrawsAroundTheCentre();

private:
    std::unique_ptr<Renderer> m_renderer;
};

void RendererTest::initTestCase() {
    QVERIFY(test::glContext());
    Result<std::unique_ptr<Renderer>> r = Renderer::create();
    QVERIFY(r.ok());
    m_renderer = std::move(*r);
}

void RendererTest::renderedHitsAreTheCpuTracersHits_data() {
    QTest::addColumn<int>("technique");
    QTest::addColumn<float>("tiling");
    QTest::newRow("exact") << static_cast<int>(Technique::Exact) << 1.0f;
    QTest::newRow("exact tiled 3x") << static_cast<int>(Technique::Exact) << 3.0f;
    QTest::newRow("relief") << static_cast<int>(Technique::Relief) << 1.0f;
    QTest::newRow("pyramid") << static_cast<int>(Technique::Pyramid) << 2.0f;
}

// Each pixel's ray, computed here from the camera (pixel centre -> the plane y = 0 -> tangent
// space, docs/conventions.md §2), traced by the CPU Tracer: the renderer's hit (surface output) is
// the same point. This pins the sign and scale of P in the render path, which the trace pass skips.
void RendererTest::renderedHitsAreTheCpuTracersHits() {
    QFETCH(int, technique);
    QFETCH(float, tiling);
    const Technique t = static_cast<Technique>(technique);
    // A smooth map, magnified: texel-level minification would pick coarser height levels.
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 32, 32, 4);
    MaterialAssets assets;
    assets.height = field;
    Result<std::unique_ptr<GpuMaterial>> gpu = GpuMaterial::create(assets, WrapMode::Repeat);
    QVERIFY(gpu.ok());
    Material m = test::sampleMaterial(t);
    m.heightScale = 0.08f;
    m.tiling = tiling;
    const OrbitCamera cam = camera(25.0f, 40.0f, 2.2f);
    DrawOptions options;
    options.output = ShaderOutput::Surface;
    options.kernels = KernelFlavour::Verify; // the kernels equal to the CPU's
    Result<Image> hits = m_renderer->renderImage(**gpu, m, cam, {}, options, kSize);
    QVERIFY(hits.ok());

    Result<Tracer> tracer = test::makeTracerFor(field, t, m);
    QVERIFY(tracer.ok());
    const glm::mat4 inverse = glm::inverse(cam.projection(1.0f) * cam.view());
    std::vector<double> errors;
    int sameFetches = 0;
    for (int y = 0; y < kSize.y; ++y) {
        for (int x = 0; x < kSize.x; ++x) {
            if (hits->at(x, y, 2) < 0.0f)
                continue; // background
            const glm::vec2 ndc((x + 0.5f) / kSize.x * 2.0f - 1.0f,
                                1.0f - (y + 0.5f) / kSize.y * 2.0f);
            glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f),
                      b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 from = glm::vec3(a) / a.w, to = glm::vec3(b) / b.w;
            const float k = from.y / (from.y - to.y);
            const glm::vec3 p = from + (to - from) * k; // on the plane y = 0
            // The plane: uv = ((x + 1) / 2, (z + 1) / 2) * tiling, T = (2, 0, 0) / tiling,
            // B = (0, 0, 2) / tiling, N = +y; Lw = 2 / tiling.
            const glm::dvec2 uv((p.x + 1.0) / 2.0 * tiling, (p.z + 1.0) / 2.0 * tiling);
            const glm::vec3 d = p - cam.position();
            const float Lw = 2.0f / tiling;
            const glm::vec3 tangent(d.x / Lw, d.z / Lw, d.y / Lw);
            const glm::vec2 P = m.heightScale * glm::vec2(tangent.x, tangent.y) / -tangent.z;
            const TraceResult cpu = tracer->trace(uv, P);
            const double du = (hits->at(x, y, 0) - cpu.u) * field.width;
            const double dv = (hits->at(x, y, 1) - cpu.v) * field.height;
            errors.push_back(std::sqrt(du * du + dv * dv));
            sameFetches += static_cast<int>(std::lround(hits->at(x, y, 3))) == cpu.fetches;
        }
    }
    QVERIFY(errors.size() > static_cast<std::size_t>(kSize.x * kSize.y / 4));
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2];
    const double p95 = errors[errors.size() * 95 / 100];
    // Rasterised uv and P differ from these in the last bits; where a ray grazes a ridge that
    // can move the hit to the other side of it, hence percentiles rather than a maximum.
    QVERIFY2(median < 0.01 && p95 < 0.05,
             qPrintable(QString("hit error: median %1, p95 %2 texels").arg(median).arg(p95)));
    QVERIFY2(
        sameFetches >= static_cast<int>(errors.size()) * 9 / 10,
        qPrintable(
            QString("%1 of %2 pixels fetch as the CPU does").arg(sameFetches).arg(errors.size())));
}

void RendererTest::renderedHitsOnLoadedMeshes_data() {
    QTest::addColumn<QString>("name");
    QTest::newRow("torus, generated tangents (obj)") << "torus.obj";
    QTest::newRow("torus, its own tangents (glb)") << "torus-tangents.glb";
    QTest::newRow("non-uniformly scaled sphere (gltf)") << "scaled.gltf";
    // Its own tangents under a glTF node's non-uniform scale (1.6, 1, 0.6): they go by the scale.
    QTest::newRow("torus, its own tangents, node scale (gltf)") << "node-scaled-tangents.gltf";
    QTest::newRow("mirrored sphere (obj)") << "mirrored.obj";
    // The same torus through a uv set twice as dense: T and B half as long, the relief half as
    // deep in the world.
    QTest::newRow("torus, second uv set twice as dense (glb)") << "two-sets.glb";
}

// As above on a loaded mesh, with the mesh's own rays: each pixel's ray meets the nearest
// front-facing triangle (found here on the CPU), where uv and the frame T, B, N are interpolated
// as the rasteriser does; the ray goes into that tangent space (P with Lw = sqrt(|T| |B|), the
// depth scale of the local uv density) and the CPU Tracer's hit is the renderer's.
void RendererTest::renderedHitsOnLoadedMeshes() {
    QFETCH(QString, name);
    QTemporaryDir dir;
    const std::string file = dir.filePath(name).toStdString();
    test::TestMesh source =
        name.startsWith("torus") || name.startsWith("two-sets") || name.startsWith("node")
            ? test::torus(32, 16, name.contains("tangents"), 20.0f)
        : name.startsWith("scaled") ? test::scaled(test::seamedSphere(32, 16), {1.6f, 1.0f, 0.6f})
                                    : test::mirroredSphere(32, 16);
    if (name.startsWith("node"))
        source.nodeScale = {1.6f, 1.0f, 0.6f};
    MeshLoadOptions load;
    if (name.startsWith("two-sets")) {
        for (const glm::vec2& uv : source.uvs)
            source.uvs2.push_back(2.0f * uv);
        load.uvSet = 1;
    }
    QVERIFY(name.endsWith(".obj") ? test::writeObj(file, source) : test::writeGltf(file, source));
    Result<LoadedMesh> loaded = loadMesh(file, load);
    QVERIFY(loaded.ok());
    QCOMPARE(loaded->fileTangents, name.contains("tangents"));
    auto mesh = std::make_shared<const MeshData>(loaded->mesh);

    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 32, 32, 4);
    MaterialAssets assets;
    assets.height = field;
    Result<std::unique_ptr<GpuMaterial>> gpu = GpuMaterial::create(assets, WrapMode::Repeat);
    QVERIFY(gpu.ok());
    Material m = test::sampleMaterial(Technique::Exact);
    m.heightScale = 0.06f;
    const OrbitCamera cam = camera(25.0f, 30.0f, 3.2f);
    DrawOptions options;
    options.customMesh = mesh;
    options.output = ShaderOutput::Surface;
    options.kernels = KernelFlavour::Verify;
    Result<Image> hits = m_renderer->renderImage(**gpu, m, cam, {}, options, kSize);
    QVERIFY(hits.ok());
    Result<Tracer> tracer = test::makeTracerFor(field, Technique::Exact, m);
    QVERIFY(tracer.ok());

    const glm::dmat4 inverse = glm::inverse(glm::dmat4(cam.projection(1.0f) * cam.view()));
    std::vector<double> errors;
    for (int y = 0; y < kSize.y; ++y) {
        for (int x = 0; x < kSize.x; ++x) {
            if (hits->at(x, y, 2) < 0.0f)
                continue;
            const glm::dvec2 ndc((x + 0.5) / kSize.x * 2.0 - 1.0, 1.0 - (y + 0.5) / kSize.y * 2.0);
            const glm::dvec4 a = inverse * glm::dvec4(ndc, -1.0, 1.0);
            const glm::dvec4 b = inverse * glm::dvec4(ndc, 1.0, 1.0);
            const glm::dvec3 from = glm::dvec3(a) / a.w, dir = glm::dvec3(b) / b.w - from;
            // The nearest front-facing triangle (Moller-Trumbore).
            double best = 1e30;
            glm::dvec3 bary(0.0);
            std::size_t triangle = 0;
            for (std::size_t i = 0; i < mesh->indices.size(); i += 3) {
                const glm::dvec3 p0(mesh->vertices[mesh->indices[i]].position);
                const glm::dvec3 e1 =
                    glm::dvec3(mesh->vertices[mesh->indices[i + 1]].position) - p0;
                const glm::dvec3 e2 =
                    glm::dvec3(mesh->vertices[mesh->indices[i + 2]].position) - p0;
                if (glm::dot(glm::cross(e1, e2), dir) >= 0.0)
                    continue; // back-facing: culled
                const glm::dvec3 q = glm::cross(dir, e2);
                const double det = glm::dot(e1, q);
                const glm::dvec3 s0 = from - p0;
                const double u = glm::dot(s0, q) / det;
                const glm::dvec3 r = glm::cross(s0, e1);
                const double v = glm::dot(dir, r) / det, t = glm::dot(e2, r) / det;
                if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0 && t < best) {
                    best = t;
                    bary = {1.0 - u - v, u, v};
                    triangle = i;
                }
            }
            if (best == 1e30)
                continue;
            auto at = [&](auto member) {
                glm::dvec3 sum(0.0);
                for (int k = 0; k < 3; ++k)
                    sum +=
                        bary[k] * glm::dvec3(mesh->vertices[mesh->indices[triangle + k]].*member);
                return sum;
            };
            glm::dvec2 uv(0.0);
            for (int k = 0; k < 3; ++k)
                uv += bary[k] * glm::dvec2(mesh->vertices[mesh->indices[triangle + k]].uv);
            const glm::dvec3 T = at(&MeshVertex::tangent), B = at(&MeshVertex::bitangent);
            const glm::dvec3 N = glm::normalize(at(&MeshVertex::normal));
            const double Lw = std::sqrt(std::max(glm::length(T) * glm::length(B), 1e-20));
            const glm::dvec3 d = glm::inverse(glm::dmat3(T, B, N * Lw)) * dir;
            const glm::vec2 P =
                boundParallax(glm::vec2(double(m.heightScale) * glm::dvec2(d.x, d.y) /
                                        std::max(-d.z, 1e-4 * glm::length(d))))
                    .P;
            const glm::dvec2 tile = glm::floor(uv);
            const TraceResult cpu = tracer->trace(uv - tile, P);
            const double du = (hits->at(x, y, 0) - (cpu.u + tile.x)) * field.width;
            const double dv = (hits->at(x, y, 1) - (cpu.v + tile.y)) * field.height;
            errors.push_back(std::sqrt(du * du + dv * dv));
        }
    }
    QVERIFY2(errors.size() > static_cast<std::size_t>(kSize.x * kSize.y / 6),
             qPrintable(QString("%1 pixels compared").arg(errors.size())));
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2], p95 = errors[errors.size() * 95 / 100];
    qInfo("%s: %zu pixels, hit error median %.2g, p95 %.2g texels", qPrintable(name), errors.size(),
          median, p95);
    QVERIFY2(median < 0.01 && p95 < 0.05,
             qPrintable(QString("hit error: median %1, p95 %2 texels").arg(median).arg(p95)));
}

// A normal map baked from the heights (docs/conventions.md §3) shades like normals derived in the
// shader; a DirectX map read as DirectX too; read as OpenGL it does not (the test can fail).
void RendererTest::normalMapAndHeightNormalsAgree() {
    MaterialAssets assets;
    assets.height = makeProceduralMap(ProceduralMap::Noise, 64, 64, 2);
    const float s = 0.08f;
    Material m = test::sampleMaterial(Technique::Normal);
    m.heightScale = s;
    const OrbitCamera cam = camera(25.0f, 40.0f, 1.6f); // magnified: filtering plays no part
    DirectionalLight light;
    light.azimuthDeg = 200.0f;
    light.elevationDeg = 35.0f;
    auto render = [&](const MaterialAssets& a, NormalSource source, NormalGreen green) {
        Result<std::unique_ptr<GpuMaterial>> gpu = GpuMaterial::create(a, WrapMode::Repeat);
        Material view = m;
        view.normalSource = source;
        view.normalGreen = green;
        return m_renderer->renderImage(**gpu, view, cam, light, {}, kSize);
    };
    Result<Image> derived = render(assets, NormalSource::HeightCentral, NormalGreen::OpenGL);
    MaterialAssets withMap = assets;
    withMap.normal = normalMapOf(assets.height, s, false);
    Result<Image> mapped = render(withMap, NormalSource::Map, NormalGreen::OpenGL);
    withMap.normal = normalMapOf(assets.height, s, true);
    Result<Image> directX = render(withMap, NormalSource::Map, NormalGreen::DirectX);
    Result<Image> misread = render(withMap, NormalSource::Map, NormalGreen::OpenGL);
    QVERIFY(derived.ok() && mapped.ok() && directX.ok() && misread.ok());
    const test::ImageDifference a = test::compareImages(*derived, *mapped, 4);
    const test::ImageDifference b = test::compareImages(*mapped, *directX, 2);
    const test::ImageDifference c = test::compareImages(*derived, *misread, 4);
    QVERIFY2(a.meanAbs < 1.5, qPrintable(QString("map vs derived: mean %1 steps").arg(a.meanAbs)));
    QVERIFY2(b.meanAbs < 0.5,
             qPrintable(QString("OpenGL vs DirectX map: mean %1 steps").arg(b.meanAbs)));
    QVERIFY2(c.meanAbs > 4.0 * std::max(a.meanAbs, 0.5),
             qPrintable(QString("a misread green: mean %1 steps only").arg(c.meanAbs)));
}

void RendererTest::derivativeFrameMatchesVertexFrame() {
    MaterialAssets assets = test::bricksAssets(64);
    Result<std::unique_ptr<GpuMaterial>> gpu = GpuMaterial::create(assets, WrapMode::Repeat);
    QVERIFY(gpu.ok());
    const Material m = test::sampleMaterial(Technique::Pom);
    DrawOptions vertex, derivative;
    derivative.tbn = TbnSource::Derivatives;
    for (MeshKind mesh : {MeshKind::Plane, MeshKind::Cube}) {
        vertex.mesh = derivative.mesh = mesh;
        Result<Image> a =
            m_renderer->renderImage(**gpu, m, camera(25, 40, 3.8f), {}, vertex, kSize);
        Result<Image> b =
            m_renderer->renderImage(**gpu, m, camera(25, 40, 3.8f), {}, derivative, kSize);
        QVERIFY(a.ok() && b.ok());
        const test::ImageDifference d = test::compareImages(*a, *b, 8);
        // Derivatives are per 2x2 quad: pixels on triangle edges may differ, nothing else.
        QVERIFY2(d.meanAbs < 1.0 && d.pixelsOver < kSize.x * kSize.y / 50,
                 qPrintable(QString("%1: mean %2, %3 pixels over 8 steps")
                                .arg(meshKindName(mesh).data())
                                .arg(d.meanAbs)
                                .arg(d.pixelsOver)));
    }
}

// With clamp, a ray that leaves the tile is discarded (the silhouette shows the relief); with
// repeat it finds the neighbouring tile. Every pixel clamp discards has its repeat hit outside
// the tile (or at its very edge, where the clamped border differs).
void RendererTest::clampDiscardsRaysLeavingTheTile() {
    MaterialAssets assets = test::bricksAssets(64, false);
    Material m = test::sampleMaterial(Technique::Exact);
    m.heightScale = 0.1f;
    DrawOptions options;
    options.output = ShaderOutput::Surface;
    const OrbitCamera cam = camera(25, 30, 3.4f);
    Result<std::unique_ptr<GpuMaterial>> repeat = GpuMaterial::create(assets, WrapMode::Repeat);
    Result<std::unique_ptr<GpuMaterial>> clamp = GpuMaterial::create(assets, WrapMode::Clamp);
    QVERIFY(repeat.ok() && clamp.ok());
    Result<Image> a = m_renderer->renderImage(**repeat, m, cam, {}, options, kSize);
    m.wrap = WrapMode::Clamp;
    Result<Image> b = m_renderer->renderImage(**clamp, m, cam, {}, options, kSize);
    QVERIFY(a.ok() && b.ok());
    int discarded = 0;
    for (int y = 0; y < kSize.y; ++y) {
        for (int x = 0; x < kSize.x; ++x) {
            const bool inRepeat = a->at(x, y, 2) >= 0.0f, inClamp = b->at(x, y, 2) >= 0.0f;
            QVERIFY(inRepeat || !inClamp); // clamp never draws where the mesh is not
            if (inRepeat && !inClamp) {
                ++discarded;
                const float u = a->at(x, y, 0), v = a->at(x, y, 1), margin = 2.0f / 64.0f;
                QVERIFY2(
                    u < margin || u > 1 - margin || v < margin || v > 1 - margin,
                    qPrintable(QString("pixel %1,%2 discarded though its hit (%3, %4) is inside")
                                   .arg(x)
                                   .arg(y)
                                   .arg(u)
                                   .arg(v)));
            }
        }
    }
    QVERIFY2(discarded > covered(*a) / 50,
             qPrintable(QString("only %1 pixels discarded").arg(discarded)));
}

void RendererTest::bakesOnlyWhatTheTechniqueReads() {
    Result<std::unique_ptr<GpuMaterial>> gpu =
        GpuMaterial::create(test::bricksAssets(32, false), WrapMode::Repeat);
    QVERIFY(gpu.ok());
    GpuMaterial& g = **gpu;
    auto draw = [&](Technique t) {
        Result<Image> image =
            m_renderer->renderImage(g, test::sampleMaterial(t), camera(), {}, {}, {32, 32});
        QVERIFY(image.ok());
    };
    for (Technique t : {Technique::None, Technique::Normal, Technique::Offset, Technique::Pom,
                        Technique::Relief, Technique::Secant, Technique::Steep, Technique::Exact})
        draw(t);
    QCOMPARE(g.bakeCount(), 0);
    QVERIFY(!g.ready(Technique::Cone) && !g.ready(Technique::RelaxedCone) &&
            !g.ready(Technique::Pyramid));
    draw(Technique::Cone);
    QCOMPARE(g.bakeCount(), 1);
    QVERIFY(g.ready(Technique::Cone) && !g.ready(Technique::RelaxedCone) &&
            !g.ready(Technique::Pyramid));
    draw(Technique::Cone);
    QCOMPARE(g.bakeCount(), 1); // baked once
    draw(Technique::Pyramid);
    QCOMPARE(g.bakeCount(), 2);
    QVERIFY(!g.ready(Technique::RelaxedCone));
    draw(Technique::RelaxedCone);
    QCOMPARE(g.bakeCount(), 3);
    // A material's own cone map is used, not re-baked.
    MaterialAssets withCone = test::bricksAssets(32, false);
    withCone.cone = ConeMap(ConeKind::Conservative, 32, 32);
    std::fill(withCone.cone.sqrtRatio.begin(), withCone.cone.sqrtRatio.end(), 0.0f);
    Result<std::unique_ptr<GpuMaterial>> given = GpuMaterial::create(withCone, WrapMode::Repeat);
    QVERIFY(given.ok());
    Result<Image> image = m_renderer->renderImage(**given, test::sampleMaterial(Technique::Cone),
                                                  camera(), {}, {}, {32, 32});
    QVERIFY(image.ok());
    QCOMPARE((*given)->bakeCount(), 0);
}

void RendererTest::mapsUploadAs16BitWhereTheyFit() {
    HeightField sixteen(8, 4);
    for (std::size_t i = 0; i < sixteen.texels.size(); ++i)
        sixteen.texels[i] = static_cast<float>(i * 2011 % 65536) / 65535.0f;
    HeightField floats = sixteen;
    floats.texels[5] = 0.1234567f;
    QVERIFY(gl::fitsR16(sixteen));
    QVERIFY(!gl::fitsR16(floats));
    // Every 16-bit level fits, read as k / 65535 or as k * (1 / 65535), and so does a 16-bit PNG
    // read back (a test of 10^-3 of a step in float rejected most levels above 8192).
    HeightField levels(256, 256);
    for (std::size_t k = 0; k < levels.texels.size(); ++k)
        levels.texels[k] = static_cast<float>(k) / 65535.0f;
    QVERIFY(gl::fitsR16(levels));
    for (std::size_t k = 0; k < levels.texels.size(); ++k)
        levels.texels[k] = static_cast<float>(k) * (1.0f / 65535.0f);
    QVERIFY(gl::fitsR16(levels));
    QTemporaryDir dir;
    const std::string png = dir.filePath("levels.png").toStdString();
    QVERIFY(writeImage(png, levels.toImage(), {PixelFormat::UInt16, false}).ok());
    Result<HeightField> read = loadHeightField(png);
    QVERIFY(read.ok());
    QVERIFY(gl::fitsR16(*read));
    levels.texels[40000] += 0.3f / 65535.0f;
    QVERIFY(!gl::fitsR16(levels));
    MaterialAssets assets;
    assets.height = sixteen;
    QVERIFY((*GpuMaterial::create(assets, WrapMode::Repeat))->heightIs16Bit());
    assets.height = floats;
    QVERIFY(!(*GpuMaterial::create(assets, WrapMode::Repeat))->heightIs16Bit());
    // Cone maps: RG16 when the heights fit R16 and the cones are on the 16-bit grid (its own
    // bakes round down to it); a cone map given in floats, or float heights, keep RG32F.
    for (const bool sixteenBitHeight : {true, false}) {
        for (const bool givenFloatCones : {false, true}) {
            MaterialAssets a;
            a.height = sixteenBitHeight ? sixteen : floats;
            if (givenFloatCones) {
                a.cone = ConeMap(ConeKind::Conservative, a.height.width, a.height.height);
                a.cone.sqrtRatio[3] = 0.1234567f;
                QVERIFY(!gl::fitsRG16(a.cone));
            }
            Result<std::unique_ptr<GpuMaterial>> m = GpuMaterial::create(a, WrapMode::Repeat);
            QVERIFY(m.ok());
            QVERIFY((*m)->prepare(Technique::Cone).ok());
            QVERIFY((*m)->prepare(Technique::RelaxedCone).ok());
            const bool rg16 = sixteenBitHeight && !givenFloatCones;
            QCOMPARE((*m)->coneMapIs16Bit(ConeKind::Conservative), rg16);
            QCOMPARE((*m)->coneMapIs16Bit(ConeKind::Relaxed), sixteenBitHeight);
        }
    }
    // What the GPU holds: every 16-bit level exactly, floats verbatim.
    for (const HeightField* f : {&sixteen, &floats}) {
        const bool r16 = gl::fitsR16(*f);
        Result<gl::Object> t =
            gl::uploadHeight(*f, r16 ? gl::HeightFormat::R16 : gl::HeightFormat::R32F);
        QVERIFY(t.ok());
        glBindTexture(GL_TEXTURE_2D, t->id());
        GLint format = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
        QCOMPARE(format, r16 ? GL_R16 : GL_R32F);
        std::vector<float> back(f->texels.size());
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, back.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        for (std::size_t i = 0; i < back.size(); ++i)
            QVERIFY2(std::abs(back[i] - f->texels[i]) <= (r16 ? 0.5f / 65535.0f : 0.0f),
                     qPrintable(QString("texel %1: %2 on the GPU, %3 in the file")
                                    .arg(i)
                                    .arg(back[i])
                                    .arg(f->texels[i])));
    }
}

namespace {

// Level 0 of `texture`, `channels` floats a texel.
std::vector<float> readBack(const gl::Object& texture, int width, int height, int channels) {
    std::vector<float> back(static_cast<std::size_t>(width) * height * channels);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0,
                  channels == 1   ? GL_RED
                  : channels == 2 ? GL_RG
                                  : GL_RGBA,
                  GL_FLOAT, back.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    return back;
}

} // namespace

// Maps go up a few MiB of rows at a time (no conversion buffer the size of the map): every band,
// the last short one too, lands on its own rows.
void RendererTest::bigMapsUploadInBandsExactly() {
    // 2100 x 1030: two bands as R16, three as R32F, five as RG32F, nine for the albedo's RGBA.
    const int w = 2100, h = 1030;
    HeightField field(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            field.at(x, y) = static_cast<float>((x * 7919 + y * 104729) % 65536) / 65535.0f;
    HeightField floats = field;
    floats.at(w - 1, h - 1) = 0.1234567f;
    ConeMap cones(ConeKind::Conservative, w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            cones.g(x, y) = static_cast<float>((x + 3 * y) % 1000) / 999.0f;
    Image albedo(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                albedo.at(x, y, c) = static_cast<float>((x + y + 100 * c) % 256) / 255.0f;
    auto mismatch = [](const std::vector<float>& back, int channels, int channel, auto expected,
                       float tolerance) -> QString {
        for (std::size_t i = 0; i < back.size() / channels; ++i) {
            const float want = expected(i);
            if (!(std::abs(back[i * channels + channel] - want) <= tolerance))
                return QString("texel %1 (row %2): %3 on the GPU, %4 expected")
                    .arg(i)
                    .arg(i / 2100)
                    .arg(back[i * channels + channel])
                    .arg(want);
        }
        return {};
    };
    Result<gl::Object> r16 = gl::uploadHeight(field, gl::HeightFormat::R16);
    Result<gl::Object> r32 = gl::uploadHeight(floats, gl::HeightFormat::R32F);
    ConeMap cones16 = cones;
    quantiseDown(cones16, 65535);
    QVERIFY(!gl::fitsRG16(cones) && gl::fitsRG16(cones16));
    Result<gl::Object> cone = gl::uploadConeMap(field, cones, gl::ConeFormat::RG32F);
    Result<gl::Object> cone16 = gl::uploadConeMap(field, cones16, gl::ConeFormat::RG16);
    Result<gl::Object> colour = gl::uploadAlbedo(albedo);
    QVERIFY(r16.ok() && r32.ok() && cone.ok() && cone16.ok() && colour.ok());
    QString bad = mismatch(
        readBack(*r16, w, h, 1), 1, 0, [&](std::size_t i) { return field.texels[i]; },
        0.5f / 65535.0f);
    QVERIFY2(bad.isEmpty(), qPrintable("R16 height: " + bad));
    bad = mismatch(
        readBack(*r32, w, h, 1), 1, 0, [&](std::size_t i) { return floats.texels[i]; }, 0.0f);
    QVERIFY2(bad.isEmpty(), qPrintable("R32F height: " + bad));
    const std::vector<float> rg = readBack(*cone, w, h, 2);
    bad = mismatch(
        rg, 2, 0, [&](std::size_t i) { return field.texels[i]; }, 0.0f);
    QVERIFY2(bad.isEmpty(), qPrintable("cone map R: " + bad));
    bad = mismatch(
        rg, 2, 1, [&](std::size_t i) { return cones.sqrtRatio[i]; }, 0.0f);
    QVERIFY2(bad.isEmpty(), qPrintable("cone map G: " + bad));
    // RG16 (three bands): the cones as rounded, to a float's last bit below 1 (llvmpipe reads k
    // as k * (1 / 65535), one ulp under k / 65535 for some k), and never wider.
    const std::vector<float> rg16 = readBack(*cone16, w, h, 2);
    bad = mismatch(
        rg16, 2, 0, [&](std::size_t i) { return field.texels[i]; }, 0.5f / 65535.0f);
    QVERIFY2(bad.isEmpty(), qPrintable("RG16 cone map R: " + bad));
    bad = mismatch(
        rg16, 2, 1, [&](std::size_t i) { return cones16.sqrtRatio[i]; }, 0x1p-24f);
    QVERIFY2(bad.isEmpty(), qPrintable("RG16 cone map G: " + bad));
    for (std::size_t i = 0; i < cones16.sqrtRatio.size(); ++i)
        QVERIFY2(rg16[i * 2 + 1] <= cones16.sqrtRatio[i],
                 qPrintable(QString("texel %1: a cone read back wider than baked").arg(i)));
    // The albedo is linear on the GPU (half floats: 1e-3 relative).
    const std::vector<float> rgba = readBack(*colour, w, h, 4);
    for (int c = 0; c < 3; ++c) {
        bad = mismatch(
            rgba, 4, c,
            [&](std::size_t i) {
                const float v = albedo.pixels[i * 3 + c];
                return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            },
            1e-3f);
        QVERIFY2(bad.isEmpty(), qPrintable(QString("albedo channel %1: ").arg(c) + bad));
    }
}

// After a bake or an undo the material's maps are mostly the same texels: a material made with
// the one before takes their textures over (no upload), and uploads only what changed.
void RendererTest::aNewMaterialKeepsTheTexturesOfUnchangedMaps() {
    const MaterialAssets before = test::bricksAssets(64);
    Result<std::unique_ptr<GpuMaterial>> first = GpuMaterial::create(before, WrapMode::Repeat);
    QVERIFY(first.ok());
    QCOMPARE((*first)->uploadCount(), 2); // height and albedo
    QVERIFY((*first)->prepare(Technique::Pyramid).ok());
    QCOMPARE((*first)->uploadCount(), 3);

    // A bake: the same height and albedo (shared texels) and a new cone map.
    MaterialAssets baked = before;
    baked.cone = bakeConeMap(before.height, WrapMode::Repeat, ConeKind::Conservative);
    Result<std::unique_ptr<GpuMaterial>> second =
        GpuMaterial::create(baked, WrapMode::Repeat, first->get());
    QVERIFY(second.ok());
    QCOMPARE((*second)->uploadCount(), 0);
    QVERIFY((*second)->ready(Technique::Pyramid)); // the pyramid came along
    QVERIFY((*second)->prepare(Technique::Cone).ok());
    QCOMPARE((*second)->uploadCount(), 1); // the cone map alone
    QCOMPARE((*second)->bakeCount(), 0);
    // It draws what a material made from scratch draws.
    Result<std::unique_ptr<GpuMaterial>> fresh = GpuMaterial::create(baked, WrapMode::Repeat);
    QVERIFY(fresh.ok());
    for (Technique t : {Technique::Cone, Technique::Pyramid, Technique::Pom}) {
        Result<Image> kept =
            m_renderer->renderImage(**second, test::sampleMaterial(t), camera(), {}, {}, {48, 48});
        Result<Image> made =
            m_renderer->renderImage(**fresh, test::sampleMaterial(t), camera(), {}, {}, {48, 48});
        QVERIFY(kept.ok() && made.ok());
        QVERIFY2(kept->pixels == made->pixels, std::string(info(t).name).c_str());
    }
    // Undo: the first maps again, every texture still there.
    Result<std::unique_ptr<GpuMaterial>> undone =
        GpuMaterial::create(before, WrapMode::Repeat, second->get());
    QVERIFY(undone.ok());
    QCOMPARE((*undone)->uploadCount(), 0);
    // An equal copy is not the same texels: it uploads (equality would cost a compare of the
    // whole map per frame); so does another wrap (the textures' sampling differs).
    MaterialAssets copied = before;
    copied.height.at(0, 0) = before.height.at(0, 0); // a write detaches the copy
    QVERIFY(!copied.height.texels.sharesWith(before.height.texels));
    QCOMPARE((*GpuMaterial::create(copied, WrapMode::Repeat, undone->get()))->uploadCount(), 1);
    QCOMPARE((*GpuMaterial::create(before, WrapMode::Clamp, undone->get()))->uploadCount(), 2);
}

void RendererTest::uniformChangesDoNotRecompile() {
    Result<std::unique_ptr<Renderer>> fresh = Renderer::create();
    QVERIFY(fresh.ok());
    Result<std::unique_ptr<GpuMaterial>> gpu =
        GpuMaterial::create(test::bricksAssets(32, false), WrapMode::Repeat);
    QVERIFY(gpu.ok());
    Material m = test::sampleMaterial(Technique::Pom);
    Result<RenderTarget> made = RenderTarget::create({32, 32}, TargetFormat::Rgba8);
    QVERIFY(made.ok());
    RenderTarget target = std::move(*made);
    target.bind();
    QVERIFY((*fresh)->draw(**gpu, m, camera(), {}, {}, {32, 32}).ok());
    const Image first = target.read();
    m.heightScale = 0.02f;
    m.params.maxLayers = 64;
    m.specular = 0.9f;
    DirectionalLight light;
    light.azimuthDeg = 10.0f;
    target.bind();
    QVERIFY((*fresh)->draw(**gpu, m, camera(60, 20, 3.0f), light, {}, {32, 32}).ok());
    QCOMPARE((*fresh)->shaders().size(), std::size_t(1));
    QVERIFY(test::compareImages(first, target.read(), 0).meanAbs >
            1.0);        // and the values took effect
    m.selfShadow = true; // a feature: a new variant
    QVERIFY((*fresh)->draw(**gpu, m, camera(), {}, {}, {32, 32}).ok());
    QCOMPARE((*fresh)->shaders().size(), std::size_t(2));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RendererTest::grazingViewsStayFinite() {
    Result<std::unique_ptr<GpuMaterial>> gpu =
        GpuMaterial::create(test::bricksAssets(32, false), WrapMode::Repeat);
    QVERIFY(gpu.ok());
    DrawOptions options;
    options.output = ShaderOutput::Surface;
    for (const TechniqueInfo& t : allTechniques()) {
        Material m = test::sampleMaterial(t.id);
        m.heightScale = 0.3f;
        for (float elevation : {0.3f, 3.0f}) {
            Result<Image> hits = m_renderer->renderImage(**gpu, m, camera(25, elevation, 2.0f), {},
                                                         options, {48, 48});
            QVERIFY(hits.ok());
            for (float v : hits->pixels)
                QVERIFY2(std::isfinite(v), t.name.data());
            for (int y = 0; y < 48; ++y) {
                for (int x = 0; x < 48; ++x) {
                    // -1: no surface; -2: seen steeper than 89 degrees (traced all the same).
                    const float depth = hits->at(x, y, 2);
                    QVERIFY(depth == -1.0f || depth == -2.0f || (depth >= 0.0f && depth <= 1.0f));
                }
            }
        }
    }
}

void RendererTest::shadowsDarkenOnlyWhereTheLightIsLow() {
    Result<std::unique_ptr<GpuMaterial>> gpu =
        GpuMaterial::create(test::bricksAssets(64), WrapMode::Repeat);
    QVERIFY(gpu.ok());
    Material m = test::sampleMaterial(Technique::Pom);
    m.heightScale = 0.1f;
    DirectionalLight low, high;
    low.elevationDeg = 25.0f;
    high.elevationDeg = 89.0f;
    auto render = [&](bool shadow, const DirectionalLight& light) {
        Material view = m;
        view.selfShadow = shadow;
        view.shadowSoftness = 0.2f;
        return *m_renderer->renderImage(**gpu, view, camera(), light, {}, kSize);
    };
    const double lit = luminance(render(false, low)), shadowed = luminance(render(true, low));
    QVERIFY2(shadowed < 0.9 * lit,
             qPrintable(QString("low light: %1 lit, %2 with shadows").arg(lit).arg(shadowed)));
    const test::ImageDifference overhead =
        test::compareImages(render(false, high), render(true, high), 4);
    QVERIFY2(overhead.meanAbs < 0.5,
             qPrintable(QString("light overhead: mean %1 steps").arg(overhead.meanAbs)));
}

void RendererTest::everyMeshDrawsAroundTheCentre() {
    Result<std::unique_ptr<GpuMaterial>> gpu =
        GpuMaterial::create(test::bricksAssets(32), WrapMode::Repeat);
    QVERIFY(gpu.ok());
    for (std::string_view name : meshKindNames()) {
        DrawOptions options;
        options.mesh = *parseMeshKind(name);
        Result<Image> image = m_renderer->renderImage(**gpu, test::sampleMaterial(Technique::Pom),
                                                      camera(30, 30, 4.5f), {}, options, {64, 64});
        QVERIFY(image.ok());
        QVERIFY2(image->at(32, 32, 3) == 1.0f, name.data()); // the centre is covered
        QVERIFY2(image->at(0, 0, 3) == 0.0f, name.data());   // a corner is not
    }
}

QTEST_APPLESS_MAIN(RendererTest)
#include "RendererTest.moc"

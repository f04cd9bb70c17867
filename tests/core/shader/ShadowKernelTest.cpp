// Soft self-shadowing (shaders/trace/shadow.glsl), run on the CPU through TraceKernel.h: the same
// code the renderer runs.

#include "parallax/sample/ProceduralMaps.h"
#include "trace/TraceKernel.h"

#include <QtTest>
#include <cmath>

using namespace px;

namespace {

struct Scene {
    HeightField field;
    kernel::TraceKernel k;

    Scene(HeightField f, float scale) : field(std::move(f)) {
        k.heightField = &field;
        k.pxMapSize = glm::ivec2(field.width, field.height);
        k.pxWrapRepeat = true;
        k.pxHeightMax = field.maxHeight();
        k.pxScale = scale;
        k.pxMinLayers = 8;
        k.pxMaxLayers = 32;
    }
    // Light from azimuth (degrees, from +u towards +v) at an elevation above the surface.
    float visible(glm::vec2 uv, float t, double azimuthDeg, double elevationDeg, float softness) {
        const double az = azimuthDeg * M_PI / 180, el = elevationDeg * M_PI / 180;
        const glm::vec3 l(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
        const glm::vec2 Q = k.pxScale * glm::vec2(l.x, l.y) / l.z;
        return k.pxSoftShadow(uv, t, Q, softness);
    }
};

} // namespace

class ShadowKernelTest : public QObject {
    Q_OBJECT

private slots:
    void flatSurfaceIsLit();
    void wallCastsAShadow();
    void softnessWidensThePenumbra();
    void topOfTheMapIsNeverShadowed();
    void fetchesAreBounded();
};

void ShadowKernelTest::flatSurfaceIsLit() {
    Scene s(makeProceduralMap(ProceduralMap::Flat, 32, 32, 1, 0.5f), 0.1f);
    s.k.pxHeightMax = 1.0f; // a taller neighbour elsewhere: the march must still find nothing
    for (double el : {20.0, 45.0, 80.0}) {
        for (float softness : {0.0f, 0.5f, 1.0f})
            QCOMPARE(s.visible({0.3f, 0.7f}, 0.5f, 30.0, el, softness), 1.0f);
    }
}

// Step map: h = 0 for u < 0.5, 1 beyond. A point on the low side near the step is in the wall's
// shadow when the light comes over the wall (+u), lit when it comes from the open side (-u).
void ShadowKernelTest::wallCastsAShadow() {
    Scene s(makeProceduralMap(ProceduralMap::Step, 64, 64), 0.05f);
    const glm::vec2 uv(0.45f, 0.5f);
    QCOMPARE(s.visible(uv, 1.0f, 0.0, 30.0, 0.0f), 0.0f);
    QCOMPARE(s.visible(uv, 1.0f, 0.0, 30.0, 0.3f), 0.0f);
    QCOMPARE(s.visible(uv, 1.0f, 180.0, 30.0, 0.0f), 1.0f);
    // Light straight over the wall's top edge from high up: the point 0.05 uv from a wall 0.05 uv
    // tall sees the edge at 45 degrees.
    QCOMPARE(s.visible(uv, 1.0f, 0.0, 70.0, 0.0f), 1.0f);
    QCOMPARE(s.visible(uv, 1.0f, 0.0, 20.0, 0.0f), 0.0f);
}

void ShadowKernelTest::softnessWidensThePenumbra() {
    Scene s(makeProceduralMap(ProceduralMap::Step, 64, 64), 0.05f);
    const glm::vec2 uv(0.45f, 0.5f);
    // Near the edge's elevation (about 45 degrees plus the bilinear ramp) the hard shadow is all
    // or nothing, the soft one partial, and more light shows as the light rises.
    int partialHard = 0;
    int partialSoft = 0;
    float previous = -1.0f;
    for (int step = 0; step <= 20; ++step) {
        const double el = 30.0 + 2.0 * step;
        const float hard = s.visible(uv, 1.0f, 0.0, el, 0.0f);
        const float soft = s.visible(uv, 1.0f, 0.0, el, 1.0f);
        partialHard += hard > 0.05f && hard < 0.95f;
        partialSoft += soft > 0.05f && soft < 0.95f;
        QVERIFY2(soft >= previous - 1e-6f, qPrintable(QString("elevation %1").arg(el)));
        previous = soft;
    }
    QVERIFY2(partialSoft >= 4 * std::max(partialHard, 1),
             qPrintable(QString("hard %1 soft %2").arg(partialHard).arg(partialSoft)));
}

void ShadowKernelTest::topOfTheMapIsNeverShadowed() {
    Scene s(makeProceduralMap(ProceduralMap::Random, 32, 32, 5), 0.3f);
    s.k.pxFetches = 0;
    QCOMPARE(s.visible({0.5f, 0.5f}, 1.0f - s.k.pxHeightMax, 45.0, 10.0, 0.0f), 1.0f);
    QCOMPARE(s.k.pxFetches, 0);
    s.k.pxScale = 0.0f; // no relief, no shadow
    QCOMPARE(s.visible({0.5f, 0.5f}, 1.0f, 45.0, 10.0, 0.0f), 1.0f);
}

void ShadowKernelTest::fetchesAreBounded() {
    Scene s(makeProceduralMap(ProceduralMap::Random, 32, 32, 9), 0.2f);
    for (double el : {1.0, 10.0, 60.0, 89.0}) {
        s.k.pxFetches = 0;
        const float v = s.visible({0.2f, 0.6f}, 1.0f, 123.0, el, 0.5f);
        QVERIFY(v >= 0.0f && v <= 1.0f);
        QVERIFY(s.k.pxFetches >= 1 && s.k.pxFetches <= s.k.pxMaxLayers + 1); // + the start height
    }
}

QTEST_APPLESS_MAIN(ShadowKernelTest)
#include "ShadowKernelTest.moc"

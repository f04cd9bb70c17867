// The trace kernels' own height sampling (shaders/trace/common.glsl, run on the CPU through
// TraceKernel.h): bilinear between texel centres, wrap and clamp at the edges, one fetch per
// sample or per cell gather, and agreement with an independent double-precision oracle.

#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"
#include "trace/TraceKernel.h"

#include <QtTest>
#include <cmath>

using namespace px;

namespace {

struct Heights {
    kernel::TraceKernel k;
    Heights(const HeightField& field, WrapMode wrap) {
        k.heightField = &field;
        k.pxMapSize = glm::ivec2(field.width, field.height);
        k.pxWrapRepeat = wrap == WrapMode::Repeat;
    }
    float operator()(float u, float v) { return k.pxHeight(glm::vec2(u, v)); }
};

HeightField twoByTwo() {
    HeightField f(2, 2);
    f.texels = {0.0f, 1.0f, 0.5f, 0.25f}; // row 0 = top (v = 0)
    return f;
}

} // namespace

class HeightSamplingTest : public QObject {
    Q_OBJECT

private slots:
    void texelCentresAndMidpoints();
    void wrapAndClampAtEdges();
    void kernelWrapIsWrapIndex();
    void agreesWithOracleEverywhere();
    void countsFetchesAndGathersCorners();
};

void HeightSamplingTest::texelCentresAndMidpoints() {
    const HeightField f = twoByTwo();
    Heights h(f, WrapMode::Clamp);
    QCOMPARE(h(0.25f, 0.25f), 0.0f);
    QCOMPARE(h(0.75f, 0.25f), 1.0f);
    QCOMPARE(h(0.25f, 0.75f), 0.5f);
    QCOMPARE(h(0.5f, 0.25f), 0.5f);
    QCOMPARE(h(0.5f, 0.5f), (0.0f + 1.0f + 0.5f + 0.25f) / 4);
}

// Texel wrapping is written twice, for the kernels (pxWrapIndex, pxNextIndex) and for the C++
// bakers and samplers (wrapIndex): they must be one rule.
void HeightSamplingTest::kernelWrapIsWrapIndex() {
    kernel::TraceKernel k;
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        k.pxWrapRepeat = mode == WrapMode::Repeat;
        for (int size : {1, 2, 3, 7, 64}) {
            for (int i = -5 * size - 3; i <= 5 * size + 3; ++i) {
                const int wrapped = wrapIndex(i, size, mode);
                QCOMPARE(k.pxWrapIndex(i, size), wrapped);
                QCOMPARE(k.pxNextIndex(wrapped, i, size), wrapIndex(i + 1, size, mode));
            }
        }
    }
}

void HeightSamplingTest::wrapAndClampAtEdges() {
    const HeightField f = twoByTwo();
    Heights clamp(f, WrapMode::Clamp);
    Heights repeat(f, WrapMode::Repeat);
    // At u = 0 the sample is half-way between texel 0 and (clamp) itself / (repeat) texel 1.
    QCOMPARE(clamp(0.0f, 0.25f), 0.0f);
    QCOMPARE(repeat(0.0f, 0.25f), 0.5f);
    QCOMPARE(repeat(1.0f, 0.25f), 0.5f);
    QCOMPARE(repeat(-1.25f, 0.25f), 1.0f); // u = 0.75 a tile to the left
    QCOMPARE(clamp(-3.0f, 0.25f), 0.0f);
    QCOMPARE(clamp(7.0f, 0.25f), 1.0f);
}

void HeightSamplingTest::agreesWithOracleEverywhere() {
    const HeightField f = makeProceduralMap(ProceduralMap::Random, 7, 5, 3);
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        Heights h(f, mode);
        for (int k = 0; k < 500; ++k) {
            const float u = -1.5f + 4.0f * (k * 0.6180339f - std::floor(k * 0.6180339f));
            const float v = -1.5f + 4.0f * (k * 0.7548776f - std::floor(k * 0.7548776f));
            QVERIFY(std::abs(h(u, v) - test::bilinearHeight(f, mode, u, v)) < 1e-6);
        }
    }
}

void HeightSamplingTest::countsFetchesAndGathersCorners() {
    const HeightField f = twoByTwo();
    Heights h(f, WrapMode::Repeat);
    QCOMPARE(h.k.pxFetches, 0);
    h(0.1f, 0.2f);
    h(0.3f, 0.4f);
    const glm::vec4 corners = h.k.pxCellCorners(glm::ivec2(1, 1));
    QCOMPARE(corners.x, 0.25f); // (1,1)
    QCOMPARE(corners.y, 0.5f);  // (0,1) wrapped
    QCOMPARE(corners.z, 1.0f);  // (1,0) wrapped
    QCOMPARE(corners.w, 0.0f);  // (0,0) wrapped
    QCOMPARE(h.k.pxFetches, 3); // two samples, one gather
}

QTEST_APPLESS_MAIN(HeightSamplingTest)
#include "HeightSamplingTest.moc"

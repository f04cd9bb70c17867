// The bilinear sampler: texel centres, midpoints, wrap and clamp at the edges, fetch counting.

#include "parallax/heightfield/Sampler.h"

#include "TestSupport.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QtTest>

using namespace px;

class SamplerTest : public QObject {
    Q_OBJECT

private slots:
    void texelCentresAndMidpoints();
    void wrapAndClampAtEdges();
    void agreesWithOracleEverywhere();
    void countsFetches();
};

namespace {
HeightField twoByTwo() {
    HeightField f(2, 2);
    f.texels = {0.0f, 1.0f, 0.5f, 0.25f}; // row 0 = top (v = 0)
    return f;
}
} // namespace

void SamplerTest::texelCentresAndMidpoints() {
    const HeightField f = twoByTwo();
    Sampler s(f, WrapMode::Clamp);
    QCOMPARE(s.sample(0.25f, 0.25f), 0.0f);
    QCOMPARE(s.sample(0.75f, 0.25f), 1.0f);
    QCOMPARE(s.sample(0.25f, 0.75f), 0.5f);
    QCOMPARE(s.sample(0.5f, 0.25f), 0.5f);
    QCOMPARE(s.sample(0.5f, 0.5f), (0.0f + 1.0f + 0.5f + 0.25f) / 4);
}

void SamplerTest::wrapAndClampAtEdges() {
    const HeightField f = twoByTwo();
    Sampler clamp(f, WrapMode::Clamp);
    Sampler repeat(f, WrapMode::Repeat);
    // At u = 0 the sample is half-way between texel 0 and (clamp) itself / (repeat) texel 1.
    QCOMPARE(clamp.sample(0.0f, 0.25f), 0.0f);
    QCOMPARE(repeat.sample(0.0f, 0.25f), 0.5f);
    QCOMPARE(repeat.sample(1.0f, 0.25f), 0.5f);
    QCOMPARE(repeat.sample(-1.25f, 0.25f), 1.0f); // u = 0.75 a tile to the left
    QCOMPARE(clamp.sample(-3.0f, 0.25f), 0.0f);
    QCOMPARE(clamp.sample(7.0f, 0.25f), 1.0f);
}

void SamplerTest::agreesWithOracleEverywhere() {
    const HeightField f = makeProceduralMap(ProceduralMap::Random, 7, 5, 3);
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        Sampler s(f, mode);
        for (int k = 0; k < 500; ++k) {
            const float u = -1.5f + 4.0f * (k * 0.6180339f - std::floor(k * 0.6180339f));
            const float v = -1.5f + 4.0f * (k * 0.7548776f - std::floor(k * 0.7548776f));
            QVERIFY(std::abs(s.sample(u, v) - test::bilinearHeight(f, mode, u, v)) < 1e-6);
        }
    }
}

void SamplerTest::countsFetches() {
    const HeightField f = twoByTwo();
    Sampler s(f, WrapMode::Repeat);
    QCOMPARE(s.fetches(), 0LL);
    s.sample(0.1f, 0.2f);
    s.sample(0.3f, 0.4f);
    float corners[4];
    s.cellCorners(1, 1, corners);
    QCOMPARE(corners[0], 0.25f); // (1,1)
    QCOMPARE(corners[1], 0.5f);  // (0,1) wrapped
    QCOMPARE(corners[2], 1.0f);  // (1,0) wrapped
    QCOMPARE(corners[3], 0.0f);  // (0,0) wrapped
    QCOMPARE(s.fetches(), 3LL);
    s.resetFetches();
    QCOMPARE(s.fetches(), 0LL);
}

QTEST_APPLESS_MAIN(SamplerTest)
#include "SamplerTest.moc"

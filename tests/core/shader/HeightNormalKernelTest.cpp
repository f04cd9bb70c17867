// Height-derived normals (shaders/trace/normals.glsl) on the CPU through TraceKernel.h: both
// filters return the exact slope of a linear ramp (docs/conventions.md §3), in uv units.

#include "trace/TraceKernel.h"

#include <QtTest>

using namespace px;

class HeightNormalKernelTest : public QObject {
    Q_OBJECT

private slots:
    void rampSlopeIsExact_data();
    void rampSlopeIsExact();
    void fetchCounts();
};

void HeightNormalKernelTest::rampSlopeIsExact_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::newRow("32x32") << 32 << 32;
    QTest::newRow("64x16") << 64 << 16;
}

void HeightNormalKernelTest::rampSlopeIsExact() {
    QFETCH(int, width);
    QFETCH(int, height);
    // h = 0.3 u + 0.2 v at texel centres, small enough to stay in [0, 1].
    HeightField field(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x)
            field.at(x, y) = 0.3f * (x + 0.5f) / width + 0.2f * (y + 0.5f) / height;
    }
    kernel::TraceKernel k;
    k.heightField = &field;
    k.pxMapSize = glm::ivec2(width, height);
    k.pxWrapRepeat = false; // clamp: the ramp has no seam inside
    for (glm::vec2 uv : {glm::vec2(0.5f, 0.5f), glm::vec2(0.31f, 0.62f), glm::vec2(0.2f, 0.8f)}) {
        const glm::vec2 central = k.pxHeightSlopeCentral(uv);
        const glm::vec2 sobel = k.pxHeightSlopeSobel(uv);
        QVERIFY2(std::abs(central.x - 0.3f) < 1e-4f && std::abs(central.y - 0.2f) < 1e-4f,
                 qPrintable(QString("central %1 %2").arg(central.x).arg(central.y)));
        QVERIFY2(std::abs(sobel.x - 0.3f) < 1e-4f && std::abs(sobel.y - 0.2f) < 1e-4f,
                 qPrintable(QString("sobel %1 %2").arg(sobel.x).arg(sobel.y)));
    }
}

void HeightNormalKernelTest::fetchCounts() {
    HeightField field(8, 8, 0.5f);
    kernel::TraceKernel k;
    k.heightField = &field;
    k.pxMapSize = glm::ivec2(8, 8);
    k.pxHeightSlopeCentral({0.5f, 0.5f});
    QCOMPARE(k.pxFetches, 4);
    k.pxFetches = 0;
    k.pxHeightSlopeSobel({0.5f, 0.5f});
    QCOMPARE(k.pxFetches, 8);
}

QTEST_APPLESS_MAIN(HeightNormalKernelTest)
#include "HeightNormalKernelTest.moc"

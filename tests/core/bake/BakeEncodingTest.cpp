// Baked maps as files: cone ratios round down, heights and maxima round up, and a cone map file
// read back is conservative for the surface its own R channel describes.

#include "parallax/bake/BakeEncoding.h"

#include "ConeChecks.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace px;

class BakeEncodingTest : public QObject {
    Q_OBJECT

private slots:
    void roundsUpToWholeSteps();
    void coneMapRoundsTheSafeWay();
    void coneMapFileIsConservative_data();
    void coneMapFileIsConservative();
    void pyramidLayouts();
};

void BakeEncodingTest::roundsUpToWholeSteps() {
    QCOMPARE(quantisationSteps(PixelFormat::UInt8), 255);
    QCOMPARE(quantisationSteps(PixelFormat::UInt16), 65535);
    QCOMPARE(quantisationSteps(PixelFormat::Float), 0);
    for (int steps : {255, 65535}) {
        for (int i = 0; i <= 5000; ++i) {
            const float v = static_cast<float>(i) / 5000.0f;
            const float r = roundUpToStep(v, steps);
            QVERIFY(r >= v);
            QVERIFY(r - v < 1.0f / steps + 1e-7f);
            QCOMPARE(std::round(r * steps), r * steps);
        }
        // Values already on a step stay there (an 8-bit map written at 8 or 16 bits is exact).
        for (int k = 0; k <= 255; ++k)
            QCOMPARE(roundUpToStep(k / 255.0f, steps), k / 255.0f);
    }
    QCOMPARE(roundUpToStep(0.123456f, 0), 0.123456f);
}

void BakeEncodingTest::coneMapRoundsTheSafeWay() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 20, 12, 3);
    const ConeMap cones = bakeConeMap(field, WrapMode::Repeat, ConeKind::Conservative);
    for (PixelFormat format : {PixelFormat::UInt8, PixelFormat::UInt16, PixelFormat::Float}) {
        const Image image = encodeConeMap(field, cones, format);
        QCOMPARE(image.channels, 3);
        for (int y = 0; y < field.height; ++y) {
            for (int x = 0; x < field.width; ++x) {
                QVERIFY(image.at(x, y, 0) >= field.at(x, y));
                QVERIFY(image.at(x, y, 1) <= cones.g(x, y));
                QCOMPARE(image.at(x, y, 2), 0.0f);
                if (format == PixelFormat::Float) {
                    QCOMPARE(image.at(x, y, 0), field.at(x, y));
                    QCOMPARE(image.at(x, y, 1), cones.g(x, y));
                }
            }
        }
    }
}

void BakeEncodingTest::coneMapFileIsConservative_data() {
    QTest::addColumn<int>("bits");
    QTest::addColumn<QString>("name");
    QTest::newRow("8-bit png") << 8 << "cone.png";
    QTest::newRow("16-bit png") << 16 << "cone.png";
    QTest::newRow("float exr") << 32 << "cone.exr";
}

// The way the command line writes a cone map: heights rounded up first, cones baked from them,
// written, read back. The file's own surface (R) lies outside the file's cones (G^2).
void BakeEncodingTest::coneMapFileIsConservative() {
    QFETCH(int, bits);
    QFETCH(QString, name);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath(name).toStdString();
    const PixelFormat format = *pixelFormatFromBits(bits);
    // A 16-bit source written at 8 bits: the heights must round.
    HeightField source = makeProceduralMap(ProceduralMap::Rivets, 18, 14, 2);
    for (float& h : source.texels)
        h = std::round(h * 65535.0f) / 65535.0f;
    const HeightField stored = roundHeightsUp(source, format);
    const ConeMap cones = bakeConeMap(stored, WrapMode::Repeat, ConeKind::Conservative);
    ImageWriteOptions options;
    options.format = format;
    QVERIFY(writeImage(path, encodeConeMap(stored, cones, format), options).ok());

    const Result<Image> read = readImage(path);
    QVERIFY(read.ok());
    HeightField surface(read->width, read->height);
    for (int y = 0; y < surface.height; ++y) {
        for (int x = 0; x < surface.width; ++x) {
            surface.at(x, y) = read->at(x, y, 0);
            QVERIFY(read->at(x, y, 0) >= source.at(x, y)); // never below the source
            QVERIFY(read->at(x, y, 1) <= cones.g(x, y));
        }
    }
    long violations = 0;
    for (int y = 0; y < surface.height; ++y) {
        for (int x = 0; x < surface.width; ++x) {
            const double g = read->at(x, y, 1);
            violations +=
                test::checkConservative(surface, WrapMode::Repeat, x, y, g * g, 6).violations;
        }
    }
    QCOMPARE(violations, 0L);
}

void BakeEncodingTest::pyramidLayouts() {
    const HeightField field = makeProceduralMap(ProceduralMap::Noise, 13, 9, 5);
    const MaxMipPyramid pyramid = MaxMipPyramid::build(field, WrapMode::Clamp);
    // Atlas: the GPU layout, maxima rounded up at 8 bits.
    const Image atlas = encodePyramid(pyramid, PyramidLayout::Atlas, -1, PixelFormat::UInt8);
    const Image exact = pyramid.atlas();
    QCOMPARE(atlas.width, exact.width);
    QCOMPARE(atlas.height, exact.height);
    for (std::size_t i = 0; i < atlas.pixels.size(); ++i) {
        QVERIFY(atlas.pixels[i] >= exact.pixels[i]);
        QVERIFY(atlas.pixels[i] - exact.pixels[i] < 1.0f / 255.0f + 1e-7f);
    }
    // Chain: level 0 on the left, levels 1.. stacked to its right.
    const Image chain = encodePyramid(pyramid, PyramidLayout::Chain, -1, PixelFormat::Float);
    QCOMPARE(chain.width, pyramid.width(0) + pyramid.width(1));
    int row = 0;
    for (int level = 0; level < pyramid.levels(); ++level) {
        const int x0 = level == 0 ? 0 : pyramid.width(0), y0 = level == 0 ? 0 : row;
        for (int y = 0; y < pyramid.height(level); ++y) {
            for (int x = 0; x < pyramid.width(level); ++x)
                QCOMPARE(chain.at(x0 + x, y0 + y), pyramid.at(level, x, y));
        }
        if (level > 0)
            row += pyramid.height(level);
    }
    // One level.
    const Image level2 = encodePyramid(pyramid, PyramidLayout::Atlas, 2, PixelFormat::Float);
    QCOMPARE(level2.width, pyramid.width(2));
    QCOMPARE(level2.at(1, 1), pyramid.at(2, 1, 1));
}

QTEST_APPLESS_MAIN(BakeEncodingTest)
#include "BakeEncodingTest.moc"

// The max-mip pyramid bounds every cell of the bilinear surface, at every level and size.

#include "parallax/bake/MaxMipPyramid.h"

#include "parallax/sample/ProceduralMaps.h"

#include <QtTest>
#include <algorithm>

using namespace px;

class MaxMipPyramidTest : public QObject {
    Q_OBJECT

private slots:
    void levelsRoundUp();
    void levelZeroIsCornerMax();
    void parentsBoundChildren();
    void atlasPacksEveryLevel();
};

void MaxMipPyramidTest::levelsRoundUp() {
    const HeightField field = makeProceduralMap(ProceduralMap::Random, 23, 5);
    const MaxMipPyramid repeat = MaxMipPyramid::build(field, WrapMode::Repeat);
    QCOMPARE(repeat.width(0), 23);
    QCOMPARE(repeat.height(0), 5);
    QCOMPARE(repeat.width(1), 12);
    QCOMPARE(repeat.height(1), 3);
    QCOMPARE(repeat.width(repeat.top()), 1);
    QCOMPARE(repeat.height(repeat.top()), 1);
    QCOMPARE(repeat.levels(), 6); // 23 -> 12 -> 6 -> 3 -> 2 -> 1
    const MaxMipPyramid clamp = MaxMipPyramid::build(field, WrapMode::Clamp);
    QCOMPARE(clamp.width(0), 24);
    QCOMPARE(clamp.height(0), 6);
    const MaxMipPyramid single =
        MaxMipPyramid::build(makeProceduralMap(ProceduralMap::Random, 1, 1), WrapMode::Repeat);
    QCOMPARE(single.levels(), 1);
}

void MaxMipPyramidTest::levelZeroIsCornerMax() {
    const HeightField f = makeProceduralMap(ProceduralMap::Random, 7, 6, 3);
    const MaxMipPyramid repeat = MaxMipPyramid::build(f, WrapMode::Repeat);
    // The seam cell (6, 5) wraps to texels 0.
    QCOMPARE(repeat.at(0, 6, 5), std::max({f.at(6, 5), f.at(0, 5), f.at(6, 0), f.at(0, 0)}));
    QCOMPARE(repeat.at(0, 2, 3), std::max({f.at(2, 3), f.at(3, 3), f.at(2, 4), f.at(3, 4)}));
    const MaxMipPyramid clamp = MaxMipPyramid::build(f, WrapMode::Clamp);
    // Stored (0, 0) is the corner border strip: only texel (0, 0).
    QCOMPARE(clamp.at(0, 0, 0), f.at(0, 0));
    QCOMPARE(clamp.at(0, 7, 2), std::max(f.at(6, 1), f.at(6, 2)));
    QCOMPARE(clamp.at(0, 3, 3), std::max({f.at(2, 2), f.at(3, 2), f.at(2, 3), f.at(3, 3)}));
}

void MaxMipPyramidTest::parentsBoundChildren() {
    const HeightField f = makeProceduralMap(ProceduralMap::Noise, 37, 19, 8);
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        const MaxMipPyramid p = MaxMipPyramid::build(f, mode);
        for (int level = 1; level < p.levels(); ++level) {
            for (int y = 0; y < p.height(level - 1); ++y) {
                for (int x = 0; x < p.width(level - 1); ++x)
                    QVERIFY(p.at(level, x / 2, y / 2) >= p.at(level - 1, x, y));
            }
        }
        QCOMPARE(p.at(p.top(), 0, 0), f.maxHeight());
    }
}

void MaxMipPyramidTest::atlasPacksEveryLevel() {
    const HeightField f = makeProceduralMap(ProceduralMap::Noise, 20, 12);
    const MaxMipPyramid p = MaxMipPyramid::build(f, WrapMode::Repeat);
    const Image atlas = p.atlas();
    QCOMPARE(atlas.width, 20);
    for (int level = 0; level < p.levels(); ++level) {
        for (int y = 0; y < p.height(level); ++y) {
            for (int x = 0; x < p.width(level); ++x)
                QCOMPARE(atlas.at(x, p.atlasRow(level) + y), p.at(level, x, y));
        }
    }
}

QTEST_APPLESS_MAIN(MaxMipPyramidTest)
#include "MaxMipPyramidTest.moc"

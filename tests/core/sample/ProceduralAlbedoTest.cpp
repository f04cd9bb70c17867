// The built-in samples' colour maps: deterministic, in range, and lined up with the relief
// (one tint per brick, mortar in the grooves).

#include "parallax/sample/ProceduralAlbedo.h"

#include <QTest>
#include <set>

using namespace px;

class ProceduralAlbedoTest : public QObject {
    Q_OBJECT
private slots:
    void bricksAreOneRegionEach() {
        const HeightField bricks = makeProceduralMap(ProceduralMap::Bricks, 256, 256);
        // 8 rows of 4 bricks; with repeat the bricks cut by the tile's edge are one brick.
        std::vector<int> labels = labelRaisedRegions(bricks, 0.16f, WrapMode::Repeat);
        QCOMPARE(*std::max_element(labels.begin(), labels.end()), 32);
        // With clamp, the odd rows' edge bricks are two halves: 4 rows of 4, 4 rows of 5.
        labels = labelRaisedRegions(bricks, 0.16f, WrapMode::Clamp);
        QCOMPARE(*std::max_element(labels.begin(), labels.end()), 36);
    }

    void colourFollowsRelief() {
        const HeightField bricks = makeProceduralMap(ProceduralMap::Bricks, 128, 128);
        const Image albedo = makeProceduralAlbedo(ProceduralMap::Bricks, bricks);
        QCOMPARE(albedo.width, 128);
        QCOMPARE(albedo.channels, 3);
        double brickRed = 0, brickBlue = 0, mortarRed = 0, mortarBlue = 0;
        int bricksN = 0, mortarN = 0;
        for (int y = 0; y < 128; ++y) {
            for (int x = 0; x < 128; ++x) {
                for (int c = 0; c < 3; ++c) {
                    QVERIFY(albedo.at(x, y, c) >= 0.0f);
                    QVERIFY(albedo.at(x, y, c) <= 1.0f);
                }
                if (bricks.at(x, y) > 0.6f) {
                    brickRed += albedo.at(x, y, 0);
                    brickBlue += albedo.at(x, y, 2);
                    ++bricksN;
                } else if (bricks.at(x, y) < 0.12f) {
                    mortarRed += albedo.at(x, y, 0);
                    mortarBlue += albedo.at(x, y, 2);
                    ++mortarN;
                }
            }
        }
        QVERIFY(bricksN > 0 && mortarN > 0);
        // Bricks are red (red well above blue); mortar is a grey (red close to blue).
        QVERIFY(brickRed / bricksN > 1.8 * brickBlue / bricksN);
        QVERIFY(mortarRed / mortarN < 1.3 * mortarBlue / mortarN);
    }

    void bricksGetDifferentTints() {
        const HeightField bricks = makeProceduralMap(ProceduralMap::Bricks, 128, 128);
        const Image albedo = makeProceduralAlbedo(ProceduralMap::Bricks, bricks);
        const std::vector<int> labels = labelRaisedRegions(bricks, 0.16f, WrapMode::Repeat);
        // Mean red per brick: several distinct tints among the 32 bricks.
        std::vector<double> sum(33, 0.0);
        std::vector<int> count(33, 0);
        for (int i = 0; i < 128 * 128; ++i) {
            if (labels[i] > 0) {
                sum[labels[i]] += albedo.pixels[static_cast<std::size_t>(i) * 3];
                ++count[labels[i]];
            }
        }
        std::set<int> tints;
        for (int l = 1; l <= 32; ++l)
            tints.insert(static_cast<int>(sum[l] / count[l] * 20.0)); // steps of 0.05
        QVERIFY(tints.size() >= 3);
    }

    void deterministic() {
        const HeightField stones = makeProceduralMap(ProceduralMap::Stones, 64, 64);
        const Image a = makeProceduralAlbedo(ProceduralMap::Stones, stones, 3);
        const Image b = makeProceduralAlbedo(ProceduralMap::Stones, stones, 3);
        QVERIFY(a.pixels == b.pixels);
        const Image c = makeProceduralAlbedo(ProceduralMap::Stones, stones, 4);
        QVERIFY(a.pixels != c.pixels);
    }
};

QTEST_MAIN(ProceduralAlbedoTest)
#include "ProceduralAlbedoTest.moc"

// Conformance on third-party data: graphics-snippets' example_1 height map and the cone map its
// author baked (G = sqrt(cone ratio), texel-centre cones, 8 bits). Ours is for the bilinear
// surface, so it may only be narrower; where the third-party map is wider than even the
// texel-centre definition allows, it is wrong. Both are checked against sampled surface points.

#include "ConeChecks.h"
#include "TestSupport.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/ConeMapFinish.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/ImageFile.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <random>

using namespace px;

namespace {

// Dummer's texel-centre cone (docs/cone-maps.md §1) with wrap, in double: the exact
// value of the definition the third-party map was baked for. Square rings of texels around b until
// no farther texel can narrow the cone.
double texelCentreCone(const HeightField& f, int bx, int by, double hMax) {
    const double hb = f.at(bx, by);
    double c = 1.0;
    const int rMax = std::max(f.width, f.height) / 2;
    for (int r = 1; r <= rMax; ++r) {
        if (static_cast<double>(r) / std::max(f.width, f.height) >= c * (hMax - hb))
            break;
        for (int oy = -r; oy <= r; ++oy) {
            for (int ox = -r; ox <= r; ox += (oy == -r || oy == r) ? 1 : 2 * r) {
                const double dh = f.at(wrapIndex(bx + ox, f.width, WrapMode::Repeat),
                                       wrapIndex(by + oy, f.height, WrapMode::Repeat)) -
                                  hb;
                if (dh > 0)
                    c = std::min(c, std::hypot(static_cast<double>(ox) / f.width,
                                               static_cast<double>(oy) / f.height) /
                                        dh);
            }
        }
    }
    return c;
}

} // namespace

class ConeMapConformanceTest : public QObject {
    Q_OBJECT

private slots:
    void example1();
};

void ConeMapConformanceTest::example1() {
    const std::string heightPath =
        test::sharedTestData("graphics-snippets/example_1_heightmap.png");
    const std::string conePath = test::sharedTestData("graphics-snippets/example_1_conemap.png");
    Result<HeightField> field = loadHeightField(heightPath);
    QVERIFY2(field.ok(), field.ok() ? "" : field.error().message.c_str());
    Result<Image> theirs = readImage(conePath);
    QVERIFY(theirs.ok());
    QCOMPARE(theirs->width, field->width);
    QCOMPARE(theirs->height, field->height);
    const int W = field->width, H = field->height;
    for (int y = 0; y < H; ++y) { // R is the height map, byte for byte
        for (int x = 0; x < W; ++x)
            QCOMPARE(theirs->at(x, y, 0), field->at(x, y));
    }

    // Ours: raw per-texel cones (like the third-party map, no 3x3 minimum), wrap, 8 bits rounded
    // down.
    ConeMap ours = *bakeQuickConeMap(*field, WrapMode::Repeat);
    quantiseDown(ours, 255);
    auto step = [](float g) { return static_cast<int>(std::lround(g * 255.0f)); };
    std::vector<int> wider; // texels where the third-party G exceeds ours
    int maxExcess = 0, oursWider = 0;
    std::vector<int> histogram(6, 0);
    for (int i = 0; i < W * H; ++i) {
        const int d = step(theirs->pixels[static_cast<std::size_t>(i) * theirs->channels + 1]) -
                      step(ours.sqrtRatio[i]);
        if (d > 0)
            wider.push_back(i);
        oursWider += d < 0;
        maxExcess = std::max(maxExcess, d);
        histogram[std::min(std::max(d, 0) / 10, 5)]++;
    }
    qInfo("their G - ours (1/255 steps): theirs wider at %zu of %d texels, by up to %d; ours wider "
          "at "
          "%d; "
          "histogram 0-9 %d, 10-19 %d, 20-29 %d, 30-39 %d, 40-49 %d, 50+ %d",
          wider.size(), W * H, maxExcess, oursWider, histogram[0], histogram[1], histogram[2],
          histogram[3], histogram[4], histogram[5]);

    // Texels to check: the 150 where theirs is widest beyond ours, and 600 at random.
    std::sort(wider.begin(), wider.end(), [&](int a, int b) {
        return theirs->pixels[a * theirs->channels + 1] - ours.sqrtRatio[a] >
               theirs->pixels[b * theirs->channels + 1] - ours.sqrtRatio[b];
    });
    std::vector<int> texels(wider.begin(),
                            wider.begin() + std::min<std::size_t>(150, wider.size()));
    std::mt19937 random(7);
    for (int i = 0; i < 600; ++i)
        texels.push_back(static_cast<int>(random() % (W * H)));

    // Theirs against the exact texel-centre cone it was meant to hold, everywhere; ours can only
    // be narrower (the bilinear surface holds every texel centre).
    const double hMax = field->maxHeight();
    long oursOverTexelCentre = 0;
    std::vector<int> excess; // their G - exact G, where positive
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            const int exact = static_cast<int>(
                std::floor(std::sqrt(texelCentreCone(*field, x, y, hMax)) * 255.0 + 1e-9));
            const int s = step(theirs->at(x, y, 1));
            if (s > exact)
                excess.push_back(s - exact);
            oursOverTexelCentre += step(ours.g(x, y)) > exact;
        }
    }
    std::sort(excess.begin(), excess.end());
    const long over11 = excess.end() - std::upper_bound(excess.begin(), excess.end(), 11);
    qInfo("theirs is wider than the exact texel-centre cone at %zu of %d texels: median %d/255, "
          "99th percentile %d/255, max %d/255; %ld texels by more than 11/255",
          excess.size(), W * H, excess.empty() ? 0 : excess[excess.size() / 2],
          excess.empty() ? 0 : excess[excess.size() * 99 / 100], excess.empty() ? 0 : excess.back(),
          over11);
    QCOMPARE(oursOverTexelCentre, 0L);
    QVERIFY(!excess.empty());

    long ourViolations = 0, theirViolations = 0;
    double theirWorst = 0;
    for (int i : texels) {
        const int x = i % W, y = i / W;
        const double cOurs = ours.ratio(x, y);
        const float gTheirs = theirs->pixels[static_cast<std::size_t>(i) * theirs->channels + 1];
        const double cTheirs = static_cast<double>(gTheirs) * gTheirs;
        ourViolations +=
            test::checkConservative(*field, WrapMode::Repeat, x, y, cOurs, 3).violations;
        const test::ConeCheck s =
            test::checkConservative(*field, WrapMode::Repeat, x, y, cTheirs, 3);
        theirViolations += s.violations > 0;
        theirWorst = std::max(theirWorst, s.worst);
    }
    qInfo(
        "sampled bilinear surface (16 points a cell) around %zu texels: ours holds no point in any "
        "cone (%ld inside); the third-party cones hold surface points at %ld of them, up to %.4f "
        "above",
        texels.size(), ourViolations, theirViolations, theirWorst);
    QCOMPARE(ourViolations, 0L);
    QVERIFY(theirViolations > 0);
}

QTEST_APPLESS_MAIN(ConeMapConformanceTest)
#include "ConeMapConformanceTest.moc"

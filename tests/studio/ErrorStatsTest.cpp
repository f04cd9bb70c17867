// A view's error readout over rendered hits: the bench's statistics, so a few pixels on another
// surface show as such (max error, share on another surface) instead of a mean above the p99.

#include "preview/ErrorStats.h"

#include "preview/VisibleRegion.h"

#include <QTest>
#include <algorithm>
#include <functional>
#include <random>

using namespace px;
using namespace px::studio;

class ErrorStatsTest : public QObject {
    Q_OBJECT
private slots:
    void outliersShowAsMaxAndOtherSurface_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {1u, 7u, 99u})
            QTest::addRow("seed%u", seed) << seed;
    }
    void outliersShowAsMaxAndOtherSurface() {
        QFETCH(unsigned, seed);
        // 1000 pixels: all but 5 hit within 0.02 texel, 5 on another surface 5..40 texels away.
        const int w = 40, h = 25, mapSide = 256;
        Image exact(w, h, 4), hits(w, h, 4);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> uv(0.0f, 1.0f), near(0.0f, 0.02f), far(5.0f, 40.0f);
        std::vector<int> outliers;
        outliers.reserve(5);
        for (int i = 0; i < 5; ++i)
            outliers.push_back(static_cast<int>(rng() % (w * h)));
        double worst = 0.0;
        int other = 0;
        for (int i = 0; i < w * h; ++i) {
            const int x = i % w, y = i / w;
            const float u = uv(rng), v = uv(rng);
            const bool outlier = std::find(outliers.begin(), outliers.end(), i) != outliers.end();
            const float off = (outlier ? far(rng) : near(rng)) / mapSide;
            exact.at(x, y, 0) = u;
            exact.at(x, y, 1) = v;
            exact.at(x, y, 2) = 0.5f;
            hits.at(x, y, 0) = u + off;
            hits.at(x, y, 1) = v;
            hits.at(x, y, 2) = 0.5f;
            hits.at(x, y, 3) = 12.0f;
            worst = std::max(worst, static_cast<double>(off) * mapSide);
            other += outlier && off * mapSide > 2.0f ? 1 : 0;
        }
        // One pixel without surface in either render is left out.
        hits.at(0, 0, 2) = -1.0f;
        const bool firstIsOutlier =
            std::find(outliers.begin(), outliers.end(), 0) != outliers.end();
        const SurfaceErrors e = compareSurfaces(hits, exact, mapSide, mapSide);
        QCOMPARE(e.pixels, w * h - 1);
        QVERIFY(e.techniqueError.p99 < 0.021);
        if (!firstIsOutlier) {
            QVERIFY(std::abs(e.techniqueError.max - worst) < 1e-3);
            QCOMPARE(e.otherSurface, other);
        }
        QVERIFY(e.otherSurface > 0);
        QVERIFY(e.techniqueError.mean >
                e.techniqueError.p99); // what the readout used to show alone
        QCOMPARE(e.meanFetches, 12.0);
    }

    // The view's surface: pixel (x, y) shows uv (u0 + x du, v0 + y dv) (tile + uv), every pixel
    // on the surface but those `hidden` says not.
    static Image entryGrid(int w, int h, double u0, double du, double v0, double dv,
                           const std::function<bool(int, int)>& hidden = {}) {
        Image entry(w, h, 4);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                entry.at(x, y, 0) = static_cast<float>(u0 + x * du);
                entry.at(x, y, 1) = static_cast<float>(v0 + y * dv);
                entry.at(x, y, 2) = hidden && hidden(x, y) ? -1.0f : 0.0f;
            }
        return entry;
    }

    // Rays whose exact hit lies where the view shows no surface (hundreds of tiles under a
    // silhouette, or on a part of the mesh out of view) are left out and counted; the figures
    // are over the rest, whatever the seed.
    void exactHitsOffTheVisibleSurfaceAreLeftOut_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {3u, 11u, 2024u, 77777u})
            QTest::addRow("seed%u", seed) << seed;
    }
    void exactHitsOffTheVisibleSurfaceAreLeftOut() {
        QFETCH(unsigned, seed);
        std::mt19937 rng(seed);
        const int w = 48, h = 32, mapSide = 64;
        // Half a tube's tile in view: u in [0.1, 0.57], v in [1.2, 1.51] (tile + uv).
        const Image entry = entryGrid(w, h, 0.1, 0.01, 1.2, 0.01);
        const VisibleRegion region(entry, mapSide, mapSide);
        Image exact(w, h, 4), hits(w, h, 4);
        std::uniform_real_distribution<double> small(-3.0, 3.0);   // texels from the entry
        std::uniform_real_distribution<double> away(100.0, 400.0); // tiles
        std::uniform_int_distribution<int> kind(0, 19);
        int off = 0;
        double worstOn = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double u = entry.at(x, y, 0) + small(rng) / mapSide;
                double v = entry.at(x, y, 1) + small(rng) / mapSide;
                const int k = kind(rng);
                if (k == 0) { // a silhouette ray: hundreds of tiles away
                    u += away(rng);
                    ++off;
                } else if (k == 1) { // the hidden half of the tube, in the same tile
                    u = 0.8 + 0.1 * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
                    ++off;
                }
                exact.at(x, y, 0) = static_cast<float>(u);
                exact.at(x, y, 1) = static_cast<float>(v);
                exact.at(x, y, 2) = 0.4f;
                const double e = std::uniform_real_distribution<double>(0.0, 0.5)(rng);
                hits.at(x, y, 0) = static_cast<float>(u + e / mapSide);
                hits.at(x, y, 1) = static_cast<float>(v);
                hits.at(x, y, 2) = 0.4f;
                hits.at(x, y, 3) = 8.0f;
                if (k > 1)
                    worstOn = std::max(worstOn, e);
            }
        const SurfaceErrors all = compareSurfaces(hits, exact, mapSide, mapSide);
        QCOMPARE(all.offRegionPixels, 0); // without a region every ray counts
        const SurfaceErrors e = compareSurfaces(hits, exact, mapSide, mapSide, &region);
        QCOMPARE(e.offRegionPixels, off);
        QCOMPARE(e.pixels, w * h - off);
        QVERIFY(e.techniqueError.max <= worstOn + 1e-3); // float uv: a few thousandths of a texel
        QVERIFY(e.techniqueError.max < 0.51);
    }

    // Two references: the technique is measured against the exact hit on the level it reads,
    // and that hit against level 0's is the filtering's error; each pixel weighs the area of
    // the texture it covers, so a part of the surface drawn with more pixels counts no more.
    void techniqueAndFilteringErrorsWeighedByArea_data() {
        QTest::addColumn<unsigned>("seed");
        const unsigned run = std::random_device{}();
        for (unsigned seed : {5u, 42u, run})
            QTest::addRow("seed%u", seed) << seed;
    }
    void techniqueAndFilteringErrorsWeighedByArea() {
        QFETCH(unsigned, seed);
        std::mt19937 rng(seed);
        const int w = 40, h = 40, mapSide = 128;
        // The top half of the view is near (0.001 tiles a pixel across), the bottom half far
        // (0.004): each bottom pixel covers 4 times the area.
        Image entry(w, h, 4), exact(w, h, 4), footprint(w, h, 4), hits(w, h, 4);
        std::uniform_real_distribution<double> small(0.0, 0.2), big(0.5, 1.5);
        double v = 0.0;
        for (int y = 0; y < h; ++y) {
            const double step = y < h / 2 ? 0.001 : 0.004;
            for (int x = 0; x < w; ++x) {
                const double u = x * step;
                entry.at(x, y, 0) = static_cast<float>(u);
                entry.at(x, y, 1) = static_cast<float>(v);
                entry.at(x, y, 2) = 0.0f;
                // Near: the technique is off by little and the filtering not at all; far: the
                // technique the same, the filtering 0.5 to 1.5 texels.
                const double te = small(rng), fe = y < h / 2 ? 0.0 : big(rng);
                for (Image* image : {&exact, &footprint, &hits}) {
                    image->at(x, y, 1) = static_cast<float>(v);
                    image->at(x, y, 2) = 0.5f;
                    image->at(x, y, 3) = 4.0f;
                }
                exact.at(x, y, 0) = static_cast<float>(u);
                footprint.at(x, y, 0) = static_cast<float>(u + fe / mapSide);
                hits.at(x, y, 0) = static_cast<float>(u + (fe + te) / mapSide);
            }
            v += step;
        }
        QVERIFY(std::abs(pixelArea(entry, 3, 3) - 0.001 * 0.001) < 1e-9);
        QVERIFY(std::abs(pixelArea(entry, 3, h - 3) - 0.004 * 0.004) < 1e-9);
        ReferenceSurfaces references;
        references.exact = &exact;
        references.footprintExact = &footprint;
        references.entry = &entry;
        const SurfaceErrors e = compareSurfaces(hits, references, mapSide, mapSide);
        QCOMPARE(e.pixels, w * h);
        QVERIFY(e.techniqueError.max < 0.21); // against the footprint's exact hit alone
        QVERIFY(e.filteringError.max > 0.5 && e.filteringError.max < 1.51);
        // The far half holds 16/17 of the area: the filtering's mean is nearly its own.
        double farMean = 0.0;
        int far = 0;
        for (int y = h / 2; y < h; ++y)
            for (int x = 0; x < w; ++x, ++far)
                farMean += e.filtering[static_cast<std::size_t>(y) * w + x];
        farMean /= far;
        const double areaShare = 16.0 / 17.0; // rows near the middle mix, a little
        QVERIFY2(std::abs(e.filteringError.mean - areaShare * farMean) < 0.03 * farMean,
                 qPrintable(QString("%1 vs %2").arg(e.filteringError.mean).arg(farMean)));
        // Counted by pixel it would be half: the test tells the two apart.
        QVERIFY(e.filteringError.mean > 0.75 * farMean);
        QVERIFY(e.area > 0.0);
        // Without the footprint's render the technique's error is against level 0.
        const SurfaceErrors total = compareSurfaces(hits, exact, mapSide, mapSide);
        QVERIFY(total.techniqueError.max > 0.5);
        QCOMPARE(total.filteringError.max, 0.0);
    }

    // Seen at a grazing angle, neighbouring pixels lie far apart in uv: the surface between them
    // is shown too. A seam (a jump of half a tile or more) joins nothing.
    void theSurfaceBetweenNeighbouringPixelsIsVisible() {
        const int mapSide = 256;
        // Rows 0.3 tiles apart (77 texels), columns 0.01 apart.
        const VisibleRegion grazing(entryGrid(20, 6, 0.0, 0.01, 0.0, 0.3), mapSide, mapSide);
        QVERIFY(grazing.contains(0.05, 0.45));
        QVERIFY(grazing.contains(0.05, 1.49));
        QVERIFY(!grazing.contains(0.05, 1.6)); // past the last row, beyond one cell
        QVERIFY(!grazing.contains(0.6, 0.45)); // beside the columns
        // Two parts of a mesh side by side on screen, a tile apart in uv: not the uv between.
        const VisibleRegion seam(entryGrid(20, 6, 0.0, 0.01, 0.0, 0.01, {}), mapSide, mapSide);
        QVERIFY(seam.contains(0.1, 0.02));
        Image twoParts = entryGrid(20, 6, 0.0, 0.01, 0.0, 0.01);
        for (int y = 0; y < 6; ++y)
            for (int x = 10; x < 20; ++x)
                twoParts.at(x, y, 0) += 1.0f;
        const VisibleRegion parts(twoParts, mapSide, mapSide);
        QVERIFY(parts.contains(0.05, 0.02));
        QVERIFY(parts.contains(1.15, 0.02));
        QVERIFY(!parts.contains(0.6, 0.02));
        // Nothing in view: nothing is.
        const VisibleRegion none(entryGrid(4, 4, 0, 0.1, 0, 0.1, [](int, int) { return true; }),
                                 mapSide, mapSide);
        QVERIFY(none.empty() && !none.contains(0.0, 0.0));
    }
};

QTEST_GUILESS_MAIN(ErrorStatsTest)
#include "ErrorStatsTest.moc"

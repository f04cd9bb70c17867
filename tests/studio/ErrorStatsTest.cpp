// A view's error readout over rendered hits: the bench's statistics, so a few pixels on another
// surface show as such (max error, share on another surface) instead of a mean above the p99.

#include "preview/ErrorStats.h"

#include <QTest>
#include <algorithm>
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
        QVERIFY(e.p99Error < 0.021);
        if (!firstIsOutlier) {
            QVERIFY(std::abs(e.maxError - worst) < 1e-3);
            QCOMPARE(e.otherSurface, other);
        }
        QVERIFY(e.otherSurface > 0);
        QVERIFY(e.meanError > e.p99Error); // what the readout used to show alone
        QCOMPARE(e.meanFetches, 12.0);
    }
};

QTEST_GUILESS_MAIN(ErrorStatsTest)
#include "ErrorStatsTest.moc"

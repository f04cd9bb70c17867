// A height map integrated from a normal map: generated heights of several kinds and seeds are
// recovered from their own normal maps (8-bit, as files store them) within stated tolerances, with
// tiling and free borders, either green convention, any size (prime sides too); a biased normal
// map makes no ramp; flat and broken input is refused.

#include "parallax/bake/HeightFromNormals.h"

#include "parallax/bake/NormalMapBaker.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace px;

namespace {

// Rounds to 8 bits, as a PNG or JPEG normal map holds it.
Image quantised(Image image) {
    for (float& v : image.pixels)
        v = std::round(v * 255.0f) / 255.0f;
    return image;
}

struct Fit {
    double rms = 0.0;   // of the difference, over the truth's range
    double worst = 0.0; // largest difference, over the range
    double scaleRatio = 0.0;
};

// Compares a derived height (in uv units: value x scale) with the truth at height scale s,
// both with their means removed.
Fit compare(const DerivedHeight& d, const HeightField& truth, float s, int border = 0) {
    double meanD = 0.0, meanT = 0.0, lo = 1e30, hi = -1e30;
    long n = 0;
    for (int y = border; y < truth.height - border; ++y)
        for (int x = border; x < truth.width - border; ++x) {
            meanD += d.height.at(x, y) * d.heightScale;
            meanT += truth.at(x, y) * s;
            lo = std::min(lo, double(truth.at(x, y)));
            hi = std::max(hi, double(truth.at(x, y)));
            ++n;
        }
    meanD /= n;
    meanT /= n;
    Fit fit;
    double sum = 0.0;
    const double range = (hi - lo) * s;
    for (int y = border; y < truth.height - border; ++y)
        for (int x = border; x < truth.width - border; ++x) {
            const double e =
                (d.height.at(x, y) * d.heightScale - meanD) - (truth.at(x, y) * s - meanT);
            sum += e * e;
            fit.worst = std::max(fit.worst, std::abs(e) / range);
        }
    fit.rms = std::sqrt(sum / n) / range;
    fit.scaleRatio = d.heightScale / range;
    return fit;
}

} // namespace

class HeightFromNormalsTest : public QObject {
    Q_OBJECT
private slots:
    void recoversGeneratedHeights_data() {
        QTest::addColumn<int>("shape");
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<bool>("directx");
        QTest::addColumn<int>("size");
        const int shapes[] = {
            static_cast<int>(ProceduralMap::Noise), static_cast<int>(ProceduralMap::Stones),
            static_cast<int>(ProceduralMap::Bricks), static_cast<int>(ProceduralMap::Rivets)};
        // Each shape under both greens (seed 8 is the DirectX row), at a power of two (128 x 144),
        // at 112 x 128 (112 = 16 x 7) and at a prime side (127 x 143; 143 = 11 x 13): sides with
        // a prime factor over 5 take another path (Dft.h), which must be as accurate.
        int directx = 0;
        for (int shape : shapes)
            for (unsigned seed : {1u, 8u, 23u}) {
                const bool dx = seed % 2 == 0;
                directx += dx;
                const int size = seed == 8u ? 112 : seed == 23u ? 127 : 128;
                QTest::addRow("shape%d-seed%u-%s-%d", shape, seed, dx ? "directx" : "opengl", size)
                    << shape << seed << dx << size;
            }
        QCOMPARE(directx, 4);
    }
    void recoversGeneratedHeights() {
        QFETCH(int, shape);
        QFETCH(unsigned, seed);
        QFETCH(bool, directx);
        QFETCH(int, size);
        const HeightField truth =
            makeProceduralMap(static_cast<ProceduralMap>(shape), size, size + 16, seed);
        NormalBakeOptions bake;
        bake.heightScale = 0.05f;
        bake.green = directx ? NormalGreen::DirectX : NormalGreen::OpenGL;
        const Image normals = quantised(*bakeNormalMap(truth, bake));
        HeightFromNormalsOptions options;
        options.green = bake.green;
        const Result<DerivedHeight> d = heightFromNormals(normals, options);
        QVERIFY2(d, d ? "" : d.error().message.c_str());
        QVERIFY(d->periodic); // the procedural maps tile, and so do their normal maps
        const Fit fit = compare(*d, truth, bake.heightScale);
        qInfo("rms %.4f worst %.4f scale ratio %.3f misfit %.3f periodic %d tilt %.4g %.4g",
              fit.rms, fit.worst, fit.scaleRatio, d->misfit, d->periodic, d->tiltU, d->tiltV);
        // Tolerances: 6% RMS and 35% at the worst texel of the relief's range (measured: 3.3-5.2%
        // RMS, 13-30% at the worst texel, at the steep edges of stones and bricks, which the
        // normal map's Sobel filter smoothed and no integration brings back); the depth within
        // 20%.
        QVERIFY2(fit.rms < 0.06 && fit.worst < 0.35,
                 qPrintable(QString("rms %1 worst %2").arg(fit.rms).arg(fit.worst)));
        QVERIFY2(std::abs(fit.scaleRatio - 1.0) < 0.2, qPrintable(QString::number(fit.scaleRatio)));
        QVERIFY(d->misfit < 0.5);
        float lo = 1.0f, hi = 0.0f;
        for (float h : d->height.texels) {
            lo = std::min(lo, h);
            hi = std::max(hi, h);
        }
        QCOMPARE(lo, 0.0f);
        QCOMPARE(hi, 1.0f);
    }

    void theWrongGreenIsWorse() {
        const HeightField truth = makeProceduralMap(ProceduralMap::Stones, 96, 96, 3);
        const Image normals = quantised(*bakeNormalMap(truth, {}));
        HeightFromNormalsOptions right, wrong;
        wrong.green = NormalGreen::DirectX;
        const Result<DerivedHeight> a = heightFromNormals(normals, right);
        const Result<DerivedHeight> b = heightFromNormals(normals, wrong);
        QVERIFY(a && b);
        QVERIFY2(b->misfit > 3.0 * a->misfit,
                 qPrintable(QString("%1 %2").arg(a->misfit).arg(b->misfit)));
        QVERIFY(compare(*b, truth, 0.05f).rms > 3.0 * compare(*a, truth, 0.05f).rms);
    }

    void freeBordersForAMapThatDoesNotTile() {
        // A ramp plus bumps: its normal map does not tile, and a ramp has no periodic height.
        for (unsigned seed : {2u, 9u}) {
            const HeightField bumps = makeProceduralMap(ProceduralMap::Noise, 96, 80, seed);
            HeightField truth(96, 80);
            for (int y = 0; y < truth.height; ++y)
                for (int x = 0; x < truth.width; ++x)
                    truth.at(x, y) = 0.5f * bumps.at(x, y) + 0.5f * x / (truth.width - 1.0f);
            NormalBakeOptions bake;
            bake.wrap = WrapMode::Clamp;
            const Image normals = quantised(*bakeNormalMap(truth, bake));
            HeightFromNormalsOptions keep;
            keep.keepTilt = true; // the ramp is the relief here
            const Result<DerivedHeight> d = heightFromNormals(normals, keep);
            QVERIFY(d);
            QVERIFY(!d->periodic);
            QCOMPARE(d->tiltU, 0.0);
            const Fit fit = compare(*d, truth, 0.05f);
            QVERIFY2(fit.rms < 0.03 && fit.worst < 0.12,
                     qPrintable(QString("rms %1 worst %2").arg(fit.rms).arg(fit.worst)));
            // Forced periodic, the ramp is lost.
            HeightFromNormalsOptions periodic;
            periodic.periodic = true;
            QVERIFY(compare(*heightFromNormals(normals, periodic), truth, 0.05f).rms > 0.1);
        }
    }

    // A tiling normal map with a bias in red and green (8-bit files off by a few levels, mean R/G
    // 115 for 128): no ramp across the tile, borders continuous when tiled, the height scale
    // that of the unbiased map, and the tilt removed said.
    void biasIsNoRamp_data() {
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<int>("bias"); // in 8-bit levels, on red and green
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::newRow("noise, -13 levels") << 3u << -13 << 96 << 80;
        QTest::newRow("stones, +6 levels, 101 x 64") << 5u << 6 << 101 << 64;
        QTest::newRow("noise, -3 levels") << 11u << -3 << 64 << 64;
    }
    void biasIsNoRamp() {
        QFETCH(unsigned, seed);
        QFETCH(int, bias);
        QFETCH(int, width);
        QFETCH(int, height);
        const HeightField truth = makeProceduralMap(
            seed == 5u ? ProceduralMap::Stones : ProceduralMap::Noise, width, height, seed);
        const Image clean = quantised(*bakeNormalMap(truth, {}));
        Image biased = clean;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < 2; ++c)
                    biased.at(x, y, c) = std::clamp(biased.at(x, y, c) + bias / 255.0f, 0.0f, 1.0f);
        const Result<DerivedHeight> a = heightFromNormals(clean);
        const Result<DerivedHeight> b = heightFromNormals(biased);
        QVERIFY(a && b);
        QVERIFY(b->periodic); // the bias does not stop a tiling map from tiling
        // The scale of the relief, not of a ramp.
        QVERIFY2(std::abs(b->heightScale / a->heightScale - 1.0) < 0.15,
                 qPrintable(QString("%1 against %2").arg(b->heightScale).arg(a->heightScale)));
        qInfo("unbiased: scale %.4g rms %.4f; biased: scale %.4g rms %.4f tilt %.4g %.4g",
              a->heightScale, compare(*a, truth, 0.05f).rms, b->heightScale,
              compare(*b, truth, 0.05f).rms, b->tiltU, b->tiltV);
        QVERIFY(compare(*b, truth, 0.05f).rms < compare(*a, truth, 0.05f).rms + 0.01);
        // No ramp: the mean height of the left and right quarters, and of the top and bottom
        // ones, differ by no more than in the unbiased result (plus 2% of the range).
        auto quarters = [](const HeightField& h, bool alongU) {
            const int n = alongU ? h.width : h.height, q = std::max(1, n / 4);
            double first = 0.0, last = 0.0;
            for (int y = 0; y < h.height; ++y)
                for (int x = 0; x < h.width; ++x) {
                    const int i = alongU ? x : y;
                    if (i < q)
                        first += h.at(x, y);
                    else if (i >= n - q)
                        last += h.at(x, y);
                }
            return std::abs(first - last) / (double(q) * (alongU ? h.height : h.width));
        };
        for (const bool u : {true, false})
            QVERIFY2(quarters(b->height, u) <= quarters(a->height, u) + 0.02,
                     qPrintable(QString("%1: %2 against %3")
                                    .arg(u ? "u" : "v")
                                    .arg(quarters(b->height, u))
                                    .arg(quarters(a->height, u))));
        // Tiled, the borders meet: the step across each seam is like the steps inside.
        double seam = 0.0, inside = 0.0;
        for (int y = 0; y < height; ++y) {
            seam =
                std::max(seam, double(std::abs(b->height.at(width - 1, y) - b->height.at(0, y))));
            for (int x = 0; x + 1 < width; ++x)
                inside =
                    std::max(inside, double(std::abs(b->height.at(x + 1, y) - b->height.at(x, y))));
        }
        QVERIFY2(seam <= inside, qPrintable(QString("seam %1 inside %2").arg(seam).arg(inside)));
        // The removed tilt is said, with the bias's sign: red up means dh/du down (§3).
        QCOMPARE(b->tiltU<0.0, bias> 0);
        QVERIFY(std::abs(b->tiltU) > std::abs(a->tiltU));
        // The same map read with free borders (as a map that does not tile is) has no ramp either.
        HeightFromNormalsOptions free;
        free.periodic = false;
        const Result<DerivedHeight> c = heightFromNormals(biased, free);
        QVERIFY(c);
        QVERIFY2(std::abs(c->heightScale / a->heightScale - 1.0) < 0.25,
                 qPrintable(QString("%1 against %2").arg(c->heightScale).arg(a->heightScale)));
    }

    void oddSizesAndTinyMaps() {
        for (auto [w, h] : {std::pair{2, 2}, {3, 5}, {37, 19}, {100, 75}}) {
            const HeightField truth = makeProceduralMap(ProceduralMap::Noise, w, h, 4);
            const Result<DerivedHeight> d = heightFromNormals(*bakeNormalMap(truth, {}));
            QVERIFY2(d || w * h <= 15, qPrintable(QString("%1x%2").arg(w).arg(h)));
            if (d && w >= 37)
                QVERIFY(compare(*d, truth, 0.05f).rms < 0.05);
        }
    }

    void refusesWhatCannotBeIntegrated() {
        Image flat(16, 16, 3);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                flat.at(x, y, 0) = flat.at(x, y, 1) = 0.5f;
                flat.at(x, y, 2) = 1.0f;
            }
        const Result<DerivedHeight> none = heightFromNormals(flat);
        QVERIFY(!none);
        QVERIFY(none.error().message.find("flat") != std::string::npos);
        QVERIFY(!heightFromNormals(Image(16, 16, 2)));
        QVERIFY(!heightFromNormals(Image(1, 16, 3)));
        std::atomic<bool> stop{true};
        BakeControl control;
        control.cancel = &stop;
        const HeightField truth = makeProceduralMap(ProceduralMap::Noise, 64, 64, 1);
        const Result<DerivedHeight> cancelled =
            heightFromNormals(*bakeNormalMap(truth, {}), {}, control);
        QVERIFY(!cancelled && isCancelled(cancelled.error()));
    }
};

QTEST_GUILESS_MAIN(HeightFromNormalsTest)
#include "HeightFromNormalsTest.moc"

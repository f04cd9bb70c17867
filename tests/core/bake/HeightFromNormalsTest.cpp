// A height map integrated from a normal map: generated heights of several kinds and seeds are
// recovered from their own normal maps (8-bit, as files store them) within stated tolerances, with
// tiling and free borders, either green convention, any size; flat and broken input is refused.

#include "parallax/bake/HeightFromNormals.h"

#include "parallax/bake/NormalMapBaker.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QtTest>
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
        for (int shape : shapes)
            for (unsigned seed : {1u, 7u, 23u})
                QTest::addRow("shape%d-seed%u", shape, seed)
                    << shape << seed << (seed % 2 == 0) << (seed == 7u ? 96 : 128);
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
            const Result<DerivedHeight> d = heightFromNormals(normals);
            QVERIFY(d);
            QVERIFY(!d->periodic);
            const Fit fit = compare(*d, truth, 0.05f);
            QVERIFY2(fit.rms < 0.03 && fit.worst < 0.12,
                     qPrintable(QString("rms %1 worst %2").arg(fit.rms).arg(fit.worst)));
            // Forced periodic, the ramp is lost.
            HeightFromNormalsOptions periodic;
            periodic.periodic = true;
            QVERIFY(compare(*heightFromNormals(normals, periodic), truth, 0.05f).rms > 0.1);
        }
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

// Normal maps per docs/conventions.md §3: exact on ramps for every filter, seamless with repeat,
// green conventions, strength set by the height scale alone; loaded maps passed through.

#include "parallax/bake/NormalMapBaker.h"

#include "parallax/sample/ProceduralMaps.h"

#include <QtTest>
#include <atomic>
#include <cmath>
#include <glm/glm.hpp>

using namespace px;

namespace {

glm::vec3 decode(const Image& image, int x, int y) {
    return glm::vec3(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)) * 2.0f - 1.0f;
}

// h = h0 + a u + b v sampled at texel centres.
HeightField ramp(int w, int h, float a, float b) {
    HeightField f(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x)
            f.at(x, y) = 0.2f + a * (x + 0.5f) / w + b * (y + 0.5f) / h;
    }
    return f;
}

Image bake(const HeightField& f, NormalFilter filter, WrapMode wrap, float scale = 0.05f,
           NormalGreen green = NormalGreen::OpenGL) {
    NormalBakeOptions o;
    o.filter = filter;
    o.wrap = wrap;
    o.heightScale = scale;
    o.green = green;
    Result<Image> r = bakeNormalMap(f, o);
    return r ? *r : Image{};
}

} // namespace

class NormalMapBakerTest : public QObject {
    Q_OBJECT

private slots:
    void rampsGiveExactSlope_data();
    void rampsGiveExactSlope();
    void signsFollowConventions();
    void repeatIsSeamless();
    void greenFlipsOnlyGreen();
    void strengthIndependentOfFilter();
    void degenerateSizes();
    void rejectsBadInput();
    void cancelsAndReportsProgress();
    void passThroughConvertsGreen();
    void detectsGreenConvention();
};

void NormalMapBakerTest::rampsGiveExactSlope_data() {
    QTest::addColumn<int>("filter");
    QTest::addColumn<int>("wrap");
    for (int f = 0; f < 3; ++f) {
        for (int w = 0; w < 2; ++w) {
            const QByteArray name = QByteArray(toString(static_cast<NormalFilter>(f)).data()) +
                                    (w ? " clamp" : " repeat");
            QTest::newRow(name.constData()) << f << w;
        }
    }
}

// Every filter is a derivative estimate: on h = a u + b v it returns (a, b) exactly, at every
// texel with clamp (edges use one-sided taps) and away from the ramp's seam with repeat.
void NormalMapBakerTest::rampsGiveExactSlope() {
    QFETCH(int, filter);
    QFETCH(int, wrap);
    const WrapMode mode = wrap ? WrapMode::Clamp : WrapMode::Repeat;
    const int W = 13, H = 9;
    const float a = 0.35f, b = -0.22f, s = 0.3f;
    const Image n = bake(ramp(W, H, a, b), static_cast<NormalFilter>(filter), mode, s);
    QCOMPARE(n.channels, 3);
    const glm::vec3 expected = glm::normalize(glm::vec3(-s * a, s * b, 1.0f));
    const int margin = mode == WrapMode::Repeat ? 1 : 0;
    for (int y = margin; y < H - margin; ++y) {
        for (int x = margin; x < W - margin; ++x) {
            const glm::vec3 got = decode(n, x, y);
            QVERIFY2(glm::length(got - expected) < 2e-6f,
                     qPrintable(QString("texel %1,%2").arg(x).arg(y)));
        }
    }
}

// Surface rising to the right tilts the normal to -X; rising down the image (+v) tilts it up the
// image, +Y in the OpenGL convention.
void NormalMapBakerTest::signsFollowConventions() {
    const Image right = bake(ramp(8, 8, 0.5f, 0.0f), NormalFilter::Central, WrapMode::Clamp);
    QVERIFY(decode(right, 4, 4).x < -0.01f);
    QVERIFY(std::abs(decode(right, 4, 4).y) < 1e-6f);
    const Image down = bake(ramp(8, 8, 0.0f, 0.5f), NormalFilter::Central, WrapMode::Clamp);
    QVERIFY(decode(down, 4, 4).y > 0.01f);
    const Image dx = bake(ramp(8, 8, 0.0f, 0.5f), NormalFilter::Central, WrapMode::Clamp, 0.05f,
                          NormalGreen::DirectX);
    QVERIFY(decode(dx, 4, 4).y < -0.01f);
}

// A tiling height map gives a tiling normal map: baking a cyclically shifted map gives the
// shifted normal map, bit for bit, including the texels next to the seam.
void NormalMapBakerTest::repeatIsSeamless() {
    const HeightField f = makeProceduralMap(ProceduralMap::Random, 17, 11, 5);
    const int sx = 5, sy = 3;
    HeightField shifted(f.width, f.height);
    for (int y = 0; y < f.height; ++y) {
        for (int x = 0; x < f.width; ++x)
            shifted.at((x + sx) % f.width, (y + sy) % f.height) = f.at(x, y);
    }
    for (int filter = 0; filter < 3; ++filter) {
        const Image a = bake(f, static_cast<NormalFilter>(filter), WrapMode::Repeat);
        const Image b = bake(shifted, static_cast<NormalFilter>(filter), WrapMode::Repeat);
        for (int y = 0; y < f.height; ++y) {
            for (int x = 0; x < f.width; ++x) {
                for (int c = 0; c < 3; ++c)
                    QCOMPARE(b.at((x + sx) % f.width, (y + sy) % f.height, c), a.at(x, y, c));
            }
        }
    }
}

void NormalMapBakerTest::greenFlipsOnlyGreen() {
    const HeightField f = makeProceduralMap(ProceduralMap::Noise, 32, 32, 2);
    const Image gl = bake(f, NormalFilter::Sobel, WrapMode::Repeat, 0.1f, NormalGreen::OpenGL);
    const Image dx = bake(f, NormalFilter::Sobel, WrapMode::Repeat, 0.1f, NormalGreen::DirectX);
    for (int y = 0; y < f.height; ++y) {
        for (int x = 0; x < f.width; ++x) {
            QCOMPARE(dx.at(x, y, 0), gl.at(x, y, 0));
            QCOMPARE(dx.at(x, y, 2), gl.at(x, y, 2));
            QVERIFY(std::abs(dx.at(x, y, 1) - (1.0f - gl.at(x, y, 1))) < 1e-6f);
        }
    }
}

// The height scale sets the strength: tan(tilt) = s |grad h| on a ramp for every filter, and
// on a smooth map the filters agree on the mean slope (they differ only in smoothing).
void NormalMapBakerTest::strengthIndependentOfFilter() {
    for (float s : {0.01f, 0.1f, 1.0f}) {
        for (int filter = 0; filter < 3; ++filter) {
            const glm::vec3 n = decode(bake(ramp(10, 10, 0.4f, 0.0f),
                                            static_cast<NormalFilter>(filter), WrapMode::Clamp, s),
                                       3, 3);
            QVERIFY(std::abs(-n.x / n.z - s * 0.4f) < 1e-5f * std::max(1.0f, s));
        }
    }
    HeightField wave(64, 64);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x)
            wave.at(x, y) = 0.5f + 0.25f * std::sin(6.2831853f * (x + 0.5f) / 64.0f) *
                                       std::cos(6.2831853f * 2.0f * (y + 0.5f) / 64.0f);
    }
    double mean[3] = {0, 0, 0};
    for (int filter = 0; filter < 3; ++filter) {
        const Image n = bake(wave, static_cast<NormalFilter>(filter), WrapMode::Repeat, 0.2f);
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                const glm::vec3 v = decode(n, x, y);
                mean[filter] += std::sqrt(v.x * v.x + v.y * v.y) / v.z;
            }
        }
    }
    QVERIFY(mean[0] > 0.0);
    QVERIFY(std::abs(mean[1] / mean[0] - 1.0) < 0.01);
    QVERIFY(std::abs(mean[2] / mean[0] - 1.0) < 0.01);
}

void NormalMapBakerTest::degenerateSizes() {
    // 1x1 and 1xN have no slope across the missing axis; flat maps and s = 0 are flat normals.
    for (WrapMode mode : {WrapMode::Repeat, WrapMode::Clamp}) {
        const Image one =
            bake(makeProceduralMap(ProceduralMap::Random, 1, 1), NormalFilter::Sobel, mode);
        QCOMPARE(decode(one, 0, 0).z, 1.0f);
        const Image column = bake(ramp(1, 6, 0.0f, 0.5f), NormalFilter::Scharr, mode);
        QCOMPARE(decode(column, 0, 2).x, 0.0f);
        QVERIFY(decode(column, 0, 2).y > 0.0f);
    }
    const Image zero = bake(makeProceduralMap(ProceduralMap::Random, 8, 8), NormalFilter::Sobel,
                            WrapMode::Repeat, 0.0f);
    QCOMPARE(decode(zero, 3, 3), glm::vec3(0, 0, 1));
}

void NormalMapBakerTest::rejectsBadInput() {
    NormalBakeOptions o;
    QVERIFY(!bakeNormalMap(HeightField{}, o).ok());
    o.heightScale = -1.0f;
    const Result<Image> negative = bakeNormalMap(HeightField(4, 4), o);
    QVERIFY(!negative.ok());
    QVERIFY(negative.error().message.find("height scale") != std::string::npos);
    o.heightScale = std::nanf("");
    QVERIFY(!bakeNormalMap(HeightField(4, 4), o).ok());
}

void NormalMapBakerTest::cancelsAndReportsProgress() {
    const HeightField f = makeProceduralMap(ProceduralMap::Noise, 256, 256);
    std::vector<float> seen;
    BakeControl control;
    control.progress = [&](float p) { seen.push_back(p); };
    QVERIFY(bakeNormalMap(f, {}, control).ok());
    QVERIFY(!seen.empty());
    QCOMPARE(seen.back(), 1.0f);
    QVERIFY(std::is_sorted(seen.begin(), seen.end()));

    std::atomic<bool> stop{true};
    control.cancel = &stop;
    const Result<Image> cancelled = bakeNormalMap(f, {}, control);
    QVERIFY(!cancelled.ok());
    QVERIFY(isCancelled(cancelled.error()));
}

void NormalMapBakerTest::passThroughConvertsGreen() {
    Image n(3, 2, 4);
    for (std::size_t i = 0; i < n.pixels.size(); ++i)
        n.pixels[i] = static_cast<float>(i % 7) / 255.0f;
    const Result<Image> same =
        convertNormalMap(n, NormalGreen::OpenGL, NormalGreen::OpenGL, "n.png");
    QVERIFY(same.ok());
    QCOMPARE(same->channels, 3);
    const Result<Image> flipped =
        convertNormalMap(n, NormalGreen::DirectX, NormalGreen::OpenGL, "n.png");
    QVERIFY(flipped.ok());
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) {
            QCOMPARE(same->at(x, y, 1), n.at(x, y, 1));
            QCOMPARE(flipped->at(x, y, 0), n.at(x, y, 0));
            QCOMPARE(flipped->at(x, y, 1), 1.0f - n.at(x, y, 1));
            QCOMPARE(flipped->at(x, y, 2), n.at(x, y, 2));
            // 8-bit values stay 8-bit values: the flip is exact.
            QCOMPARE(std::round(flipped->at(x, y, 1) * 255.0f) / 255.0f, flipped->at(x, y, 1));
        }
    }
    Image rg(1, 1, 2);
    rg.at(0, 0, 0) = 0.5f;
    rg.at(0, 0, 1) = 0.5f;
    const Result<Image> rebuilt =
        convertNormalMap(rg, NormalGreen::OpenGL, NormalGreen::OpenGL, "rg.png");
    QVERIFY(rebuilt.ok());
    QCOMPARE(rebuilt->at(0, 0, 2), 1.0f);
    const Result<Image> grey =
        convertNormalMap(Image(2, 2, 1), NormalGreen::OpenGL, NormalGreen::OpenGL, "grey.png");
    QVERIFY(!grey.ok());
    QVERIFY(grey.error().message.find("grey.png") == 0);
}

void NormalMapBakerTest::detectsGreenConvention() {
    const HeightField f = makeProceduralMap(ProceduralMap::Bricks, 64, 64);
    for (NormalGreen green : {NormalGreen::OpenGL, NormalGreen::DirectX}) {
        const Image n = bake(f, NormalFilter::Sobel, WrapMode::Repeat, 0.05f, green);
        const Result<NormalGreen> told = detectNormalGreen(n, f, WrapMode::Repeat, "n.png");
        QVERIFY(told.ok());
        QCOMPARE(*told, green);
        // A normal map of another resolution still tells.
        const HeightField big = makeProceduralMap(ProceduralMap::Bricks, 128, 128);
        const Result<NormalGreen> scaled = detectNormalGreen(n, big, WrapMode::Repeat, "n.png");
        QVERIFY(scaled.ok());
        QCOMPARE(*scaled, green);
    }
    const Image flat = bake(HeightField(8, 8, 0.5f), NormalFilter::Sobel, WrapMode::Repeat);
    QVERIFY(!detectNormalGreen(flat, HeightField(8, 8, 0.5f), WrapMode::Repeat, "flat.png").ok());
}

QTEST_APPLESS_MAIN(NormalMapBakerTest)
#include "NormalMapBakerTest.moc"

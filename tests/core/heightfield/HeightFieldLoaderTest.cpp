// Loading height maps: every format keeps its precision; every bad input is a clear error.

#include "parallax/heightfield/HeightFieldLoader.h"

#include "parallax/image/ImageFile.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <fstream>
#include <random>

using namespace px;

class HeightFieldLoaderTest : public QObject {
    Q_OBJECT

private slots:
    void init() { QVERIFY(m_dir.isValid()); }
    void formatsKeepPrecision_data();
    void formatsKeepPrecision();
    void channelsInvertAndLuminance();
    void missingFile();
    void emptyFile();
    void notAnImage();
    void truncatedFile();
    void nonFiniteTexels();
    void tooLarge();
    void outOfRangeFloat();
    void missingChannel();
    void alphaOnlyExrNeedsTheAlphaChannel();
    void floatMapReadByItsRange_data();
    void floatMapReadByItsRange();
    void recordedRangeKeptWhereItFits();
    void oneValueOutsideUnitIsRefused();

private:
    std::string path(const char* name) const { return m_dir.filePath(name).toStdString(); }
    QTemporaryDir m_dir;
};

namespace {

Image gradient(int w, int h, int channels) {
    Image image(w, h, channels);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int c = 0; c < channels; ++c)
                image.at(x, y, c) = static_cast<float>((x + y * w) % 65536) / 65535.0f;
        }
    }
    return image;
}

} // namespace

void HeightFieldLoaderTest::formatsKeepPrecision_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("format");
    QTest::addColumn<double>("tolerance");
    QTest::newRow("png8") << "h.png" << int(PixelFormat::UInt8) << 0.5 / 255;
    QTest::newRow("png16") << "h16.png" << int(PixelFormat::UInt16) << 0.5 / 65535;
    QTest::newRow("tif16") << "h.tif" << int(PixelFormat::UInt16) << 0.5 / 65535;
    QTest::newRow("tif float") << "hf.tif" << int(PixelFormat::Float) << 0.0;
    QTest::newRow("exr float") << "h.exr" << int(PixelFormat::Float) << 0.0;
    QTest::newRow("bmp") << "h.bmp" << int(PixelFormat::UInt8) << 0.5 / 255;
    QTest::newRow("tga") << "h.tga" << int(PixelFormat::UInt8) << 0.5 / 255;
    QTest::newRow("jpeg") << "h.jpg" << int(PixelFormat::UInt8) << 3.0 / 255; // lossy
}

void HeightFieldLoaderTest::formatsKeepPrecision() {
    QFETCH(QString, name);
    QFETCH(int, format);
    QFETCH(double, tolerance);
    const std::string file = path(name.toUtf8().constData());
    const Image source = gradient(300, 3, name.endsWith(".bmp") || name.endsWith(".jpg") ? 3 : 1);
    ImageWriteOptions options;
    options.format = static_cast<PixelFormat>(format);
    const Status written = writeImage(file, source, options);
    QVERIFY2(written.ok(), written.ok() ? "" : written.error().message.c_str());
    Result<HeightField> field = loadHeightField(file);
    QVERIFY2(field.ok(), field.ok() ? "" : field.error().message.c_str());
    QCOMPARE(field->width, 300);
    QCOMPARE(field->height, 3);
    double worst = 0;
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 300; ++x)
            worst = std::max(worst, std::abs(double(field->at(x, y)) - source.at(x, y, 0)));
    }
    QVERIFY2(worst <= tolerance + 1e-7, qPrintable(QString("worst error %1").arg(worst)));
}

void HeightFieldLoaderTest::channelsInvertAndLuminance() {
    Image rgba(2, 1, 4);
    const float texel[4] = {0.2f, 0.4f, 0.6f, 0.8f};
    for (int x = 0; x < 2; ++x) {
        for (int c = 0; c < 4; ++c)
            rgba.at(x, 0, c) = texel[c];
    }
    const std::string file = path("rgba.exr");
    ImageWriteOptions options;
    options.format = PixelFormat::Float;
    QVERIFY(writeImage(file, rgba, options).ok());
    HeightLoadOptions load;
    QCOMPARE(loadHeightField(file, load)->at(0, 0), 0.2f);
    load.channel = HeightChannel::Green;
    QCOMPARE(loadHeightField(file, load)->at(0, 0), 0.4f);
    load.channel = HeightChannel::Alpha;
    QCOMPARE(loadHeightField(file, load)->at(1, 0), 0.8f);
    load.invert = true;
    QCOMPARE(loadHeightField(file, load)->at(1, 0), 1.0f - 0.8f);
    load.invert = false;
    load.channel = HeightChannel::Luminance;
    QVERIFY(std::abs(loadHeightField(file, load)->at(0, 0) -
                     (0.2126f * 0.2f + 0.7152f * 0.4f + 0.0722f * 0.6f)) < 1e-6f);
}

void HeightFieldLoaderTest::missingFile() {
    const auto r = loadHeightField(path("nothere.png"));
    QVERIFY(!r.ok());
    QVERIFY(r.error().message.find("nothere.png") != std::string::npos);
    QVERIFY(r.error().message.find("no such file") != std::string::npos);
}

void HeightFieldLoaderTest::emptyFile() {
    std::ofstream(path("empty.png")).close();
    const auto r = loadHeightField(path("empty.png"));
    QVERIFY(!r.ok());
    QVERIFY(r.error().message.find("empty.png") != std::string::npos);
    QVERIFY(r.error().message.find("empty") != std::string::npos);
}

void HeightFieldLoaderTest::notAnImage() {
    std::ofstream(path("text.png")) << "this is not a PNG file at all\n";
    const auto r = loadHeightField(path("text.png"));
    QVERIFY(!r.ok());
    QVERIFY(r.error().message.find("text.png") != std::string::npos);
    QVERIFY(r.error().message.find("not a readable image") != std::string::npos);
}

void HeightFieldLoaderTest::truncatedFile() {
    const std::string file = path("cut.png");
    Image noise(256, 256, 1);
    for (std::size_t i = 0; i < noise.pixels.size(); ++i)
        noise.pixels[i] = static_cast<float>((i * 2654435761u) % 251) / 250.0f;
    QVERIFY(writeImage(file, noise, {}).ok());
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size() / 2);
    const auto r = loadHeightField(file);
    QVERIFY(!r.ok());
    QVERIFY(r.error().message.find("cut.png") != std::string::npos);
}

void HeightFieldLoaderTest::nonFiniteTexels() {
    Image image(5, 4, 1);
    image.at(3, 1) = std::nanf("");
    image.at(4, 2) = INFINITY;
    const std::string file = path("nan.exr");
    ImageWriteOptions options;
    options.format = PixelFormat::Float;
    QVERIFY(writeImage(file, image, options).ok());
    const auto r = loadHeightField(file);
    QVERIFY(!r.ok());
    const std::string& m = r.error().message;
    QVERIFY2(m.find("nan.exr") != std::string::npos, m.c_str());
    QVERIFY2(m.find("2 NaN or infinite values") != std::string::npos, m.c_str());
    QVERIFY2(m.find("(3, 1)") != std::string::npos, m.c_str());
    // A float map read by its range refuses them the same way: no range is made of a NaN.
    const auto fitted = loadHeightFieldFitted(file);
    QVERIFY(!fitted.ok());
    QCOMPARE(QString::fromStdString(fitted.error().message), QString::fromStdString(m));
}

void HeightFieldLoaderTest::tooLarge() {
    const std::string file = path("wide.png");
    QVERIFY(writeImage(file, Image(16385, 1, 1), {}).ok());
    const auto refused = loadHeightField(file);
    QVERIFY(!refused.ok());
    QVERIFY(refused.error().message.find("16384") != std::string::npos);
    HeightLoadOptions allow;
    allow.allowLarge = true;
    QVERIFY(loadHeightField(file, allow).ok());
}

void HeightFieldLoaderTest::outOfRangeFloat() {
    Image image(3, 1, 1);
    image.pixels = {-2.0f, 0.5f, 6.0f};
    const std::string file = path("range.exr");
    ImageWriteOptions options;
    options.format = PixelFormat::Float;
    QVERIFY(writeImage(file, image, options).ok());
    const auto refused = loadHeightField(file);
    QVERIFY(!refused.ok());
    QVERIFY2(refused.error().message.find("[-2, 6]") != std::string::npos,
             refused.error().message.c_str());
    HeightLoadOptions normalize;
    normalize.normalize = true;
    const auto r = loadHeightField(file, normalize);
    QVERIFY(r.ok());
    QCOMPARE(r->at(0, 0), 0.0f);
    QCOMPARE(r->at(1, 0), 0.3125f);
    QCOMPARE(r->at(2, 0), 1.0f);
}

void HeightFieldLoaderTest::missingChannel() {
    const std::string file = path("grey.png");
    QVERIFY(writeImage(file, Image(4, 4, 1), {}).ok());
    HeightLoadOptions options;
    options.channel = HeightChannel::Blue;
    const auto r = loadHeightField(file, options);
    QVERIFY(!r.ok());
    QVERIFY(r.error().message.find("1 channel") != std::string::npos);
}

// An EXR whose only channel is "A" (a mask exported alone): read as red by default it would
// silently be the alpha; it is refused with the option that reads it.
void HeightFieldLoaderTest::alphaOnlyExrNeedsTheAlphaChannel() {
    const std::string file = path("mask.exr");
    OIIO::ImageSpec spec(2, 1, 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"A"};
    spec.alpha_channel = 0;
    auto out = OIIO::ImageOutput::create(file);
    QVERIFY(out && out->open(file, spec));
    const float texels[2] = {0.25f, 0.75f};
    QVERIFY(out->write_image(OIIO::TypeDesc::FLOAT, texels));
    QVERIFY(out->close());
    const auto refused = loadHeightField(file);
    QVERIFY(!refused.ok());
    QCOMPARE(QString::fromStdString(refused.error().message),
             QString::fromStdString(file + ": the image's only channel is alpha (A): say "
                                           "--channel alpha to read the height from it"));
    HeightLoadOptions load;
    load.channel = HeightChannel::Alpha;
    const auto alpha = loadHeightField(file, load);
    QVERIFY(alpha.ok());
    QCOMPARE(alpha->at(1, 0), 0.75f);
}

namespace {

// A float height map of rough noise over [lo, lo + span], `seed` choosing the noise; the ends
// are hit exactly (a texel at each).
Image floatRelief(float lo, float span, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Image image(23, 17, 1);
    for (float& v : image.pixels)
        v = lo + span * unit(rng);
    image.at(static_cast<int>(seed % 23), 3) = lo;
    image.at(5, static_cast<int>(seed % 17)) = lo + span;
    return image;
}

} // namespace

// Float height maps in their makers' units: signed, large, tiny, far from 0. Each is read as
// stored over its own [min, max], which comes back to be recorded; read again by that range it
// gives the same heights, and by no range it is refused, never clamped.
void HeightFieldLoaderTest::floatMapReadByItsRange_data() {
    QTest::addColumn<float>("lo");
    QTest::addColumn<float>("span");
    QTest::addColumn<bool>("ranged");
    QTest::addColumn<unsigned>("seed");
    for (unsigned seed : {1u, 2u, 3u}) {
        const float f = 1.0f + 0.37f * static_cast<float>(seed);
        QTest::addRow("signed-%u", seed) << -0.6f * f << 1.1f * f << true << seed;
        QTest::addRow("centimetres-%u", seed) << 120.0f * f << 3500.0f * f << true << seed;
        QTest::addRow("tiny-signed-%u", seed) << -2e-5f * f << 5e-5f * f << true << seed;
        QTest::addRow("far-from-zero-%u", seed) << 1000.0f * f << 0.25f * f << true << seed;
        QTest::addRow("above-one-%u", seed) << 0.2f * f << 1.5f << true << seed;
        QTest::addRow("within-unit-%u", seed) << 0.1f * f << 0.5f << false << seed;
    }
}

void HeightFieldLoaderTest::floatMapReadByItsRange() {
    QFETCH(float, lo);
    QFETCH(float, span);
    QFETCH(bool, ranged);
    QFETCH(unsigned, seed);
    const Image image = floatRelief(lo, span, seed);
    const std::string file = path("relief.exr");
    ImageWriteOptions write;
    write.format = PixelFormat::Float;
    QVERIFY(writeImage(file, image, write).ok());
    float min = image.pixels[0], max = image.pixels[0];
    for (float v : image.pixels) {
        min = std::min(min, v);
        max = std::max(max, v);
    }

    const auto fitted = loadHeightFieldFitted(file);
    QVERIFY2(fitted.ok(), fitted.ok() ? "" : fitted.error().message.c_str());
    QCOMPARE(fitted->range.has_value(), ranged);
    if (!ranged) { // within [0, 1]: as stored, like a PNG
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            QCOMPARE(fitted->field.texels[i], image.pixels[i]);
        return;
    }
    QCOMPARE(fitted->range->lo, min);
    QCOMPARE(fitted->range->hi, max);
    QCOMPARE(fitted->field.minHeight(), 0.0f);
    QCOMPARE(fitted->field.maxHeight(), 1.0f);
    double worst = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const double want = (double(image.pixels[i]) - min) / (double(max) - min);
        worst = std::max(worst, std::abs(fitted->field.texels[i] - want));
    }
    QVERIFY2(worst <= 1e-6, qPrintable(QString("off by %1").arg(worst)));

    HeightLoadOptions byRange;
    byRange.range = fitted->range;
    byRange.invert = true;
    const auto again = loadHeightField(file, byRange);
    QVERIFY(again.ok());
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        QCOMPARE(again->texels[i], 1.0f - fitted->field.texels[i]);
    const auto refused = loadHeightField(file);
    QVERIFY(!refused.ok());
    QVERIFY2(refused.error().message.starts_with(file + ": height values span ") &&
                 refused.error().message.find("\"range\": [lo, hi]") != std::string::npos,
             refused.error().message.c_str());
}

// The material's own range is kept while the file's values lie within it (a hand-set, wider
// range means what it says); a file that left it is refitted by import and refused by loading.
void HeightFieldLoaderTest::recordedRangeKeptWhereItFits() {
    const Image image = floatRelief(-3.0f, 5.0f, 7); // [-3, 2]
    const std::string file = path("signed.exr");
    ImageWriteOptions write;
    write.format = PixelFormat::Float;
    QVERIFY(writeImage(file, image, write).ok());
    HeightLoadOptions wide;
    wide.range = HeightRange{-4.0f, 4.0f};
    const auto kept = loadHeightFieldFitted(file, wide);
    QVERIFY(kept.ok());
    QVERIFY(kept->range == wide.range);
    QCOMPARE(kept->field.minHeight(), 0.125f); // (-3 + 4) / 8
    QCOMPARE(kept->field.maxHeight(), 0.75f);  // (2 + 4) / 8

    HeightLoadOptions narrow;
    narrow.range = HeightRange{-1.0f, 1.0f};
    const auto refitted = loadHeightFieldFitted(file, narrow);
    QVERIFY(refitted.ok());
    QVERIFY((refitted->range == HeightRange{-3.0f, 2.0f}));
    const auto refused = loadHeightField(file, narrow);
    QVERIFY(!refused.ok());
    QCOMPARE(QString::fromStdString(refused.error().message),
             QString::fromStdString(file + ": height values span [-3, 2], outside the material's "
                                           "height range [-1, 1]: it is not the file the range "
                                           "was recorded from; import it again, or correct "
                                           "/height/range"));
}

void HeightFieldLoaderTest::oneValueOutsideUnitIsRefused() {
    const std::string file = path("flat.exr");
    ImageWriteOptions write;
    write.format = PixelFormat::Float;
    Image image(6, 5, 1);
    for (float& v : image.pixels)
        v = 5.5f;
    QVERIFY(writeImage(file, image, write).ok());
    const auto refused = loadHeightFieldFitted(file);
    QVERIFY(!refused.ok());
    QCOMPARE(QString::fromStdString(refused.error().message),
             QString::fromStdString(file + ": every height texel holds 5.5, outside [0, 1]: one "
                                           "value gives no range to read a relief by"));
    // One value within [0, 1] is a flat relief, read as stored.
    for (float& v : image.pixels)
        v = 0.25f;
    QVERIFY(writeImage(file, image, write).ok());
    const auto flat = loadHeightFieldFitted(file);
    QVERIFY(flat.ok() && !flat->range);
    QCOMPARE(flat->field.maxHeight(), 0.25f);
}

QTEST_APPLESS_MAIN(HeightFieldLoaderTest)
#include "HeightFieldLoaderTest.moc"

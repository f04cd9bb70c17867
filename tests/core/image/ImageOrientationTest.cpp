// Files are read upright, as a viewer shows them, and the reader says so: EXIF Orientation in JPEGs
// and the Orientation tag in TIFFs (all eight, seeded non-square noise), checked texel by texel: a
// grey JPEG against Qt's reader with its automatic transform (libjpeg decodes both), a TIFF against
// OpenImageIO's ImageBufAlgo::reorient, except that 2.4.7 swaps 5 and 7 (transpose and transverse;
// EXIF, Qt and jpegtran agree on 5 = transpose), so those two are taken from the other; a Radiance
// HDR stored bottom-up (+Y) reads as the same rows top-down (-Y) turned over.

#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <QImage>
#include <QImageReader>
#include <QTemporaryDir>
#include <QtTest>
#include <random>

using namespace px;

namespace {

std::vector<std::string> g_notes;
void keepNote(const std::string& note) {
    g_notes.push_back(note);
}

} // namespace

class ImageOrientationTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setImageNoteSink(keepNote); }
    void everyOrientation_data();
    void everyOrientation();
    void radianceBottomUp();

private:
    QTemporaryDir m_dir;
};

void ImageOrientationTest::everyOrientation_data() {
    QTest::addColumn<QString>("extension");
    QTest::addColumn<int>("orientation");
    for (const char* ext : {"tif", "jpg"})
        for (int o = 1; o <= 8; ++o)
            QTest::addRow("%s orientation %d", ext, o) << ext << o;
}

void ImageOrientationTest::everyOrientation() {
    QFETCH(QString, extension);
    QFETCH(int, orientation);
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    const int w = 8 + static_cast<int>(rng() % 90), h = 8 + static_cast<int>(rng() % 90);
    const int channels = extension == "jpg" ? 1 : 1 + static_cast<int>(rng() % 4);
    std::vector<float> texels(static_cast<std::size_t>(w) * h * channels);
    for (float& t : texels)
        t = std::uniform_real_distribution<float>(0, 1)(rng);
    const std::string file = m_dir.filePath("o." + extension).toStdString();
    {
        auto out = OIIO::ImageOutput::create(file);
        OIIO::ImageSpec spec(w, h, channels,
                             extension == "jpg" ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
        spec.attribute("Orientation", orientation);
        QVERIFY(out && out->open(file, spec) &&
                out->write_image(OIIO::TypeDesc::FLOAT, texels.data()) && out->close());
    }
    std::vector<float> want;
    int wantW = 0, wantH = 0;
    if (extension == "jpg") {
        QImageReader reader(QString::fromStdString(file));
        reader.setAutoTransform(true);
        const QImage shown = reader.read().convertToFormat(QImage::Format_Grayscale8);
        QVERIFY(!shown.isNull());
        wantW = shown.width();
        wantH = shown.height();
        for (int y = 0; y < wantH; ++y)
            for (int x = 0; x < wantW; ++x)
                want.push_back(static_cast<float>(shown.constScanLine(y)[x]) * (1.0f / 255.0f));
    } else {
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        OIIO::ImageBuf stored(file, 0, 0, nullptr, &config);
        QCOMPARE(stored.spec().get_int_attribute("Orientation", 1), orientation);
        if (orientation == 5 || orientation == 7)
            stored.specmod().attribute("Orientation", 12 - orientation);
        const OIIO::ImageBuf shown = OIIO::ImageBufAlgo::reorient(stored);
        wantW = shown.spec().width;
        wantH = shown.spec().height;
        want.resize(static_cast<std::size_t>(wantW) * wantH * channels);
        QVERIFY(shown.get_pixels(OIIO::ROI(0, wantW, 0, wantH, 0, 1, 0, channels),
                                 OIIO::TypeDesc::FLOAT, want.data()));
    }

    g_notes.clear();
    const Result<Image> image = readImage(file);
    QVERIFY2(image.ok(), image.ok() ? "" : image.error().message.c_str());
    const QString what = QString("seed %1: %2x%3").arg(seed).arg(w).arg(h);
    QCOMPARE(image->width, wantW);
    QCOMPARE(image->height, wantH);
    QCOMPARE(image->pixels.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i)
        if (image->pixels[i] != want[i])
            QFAIL(qPrintable(what + QString(": value %1 differs").arg(i)));
    // Said once, naming the file, for every orientation but the plain one.
    QCOMPARE(g_notes.size(), orientation == 1 ? std::size_t(0) : std::size_t(1));
    if (orientation != 1) {
        QVERIFY2(g_notes[0].rfind(file + ": ", 0) == 0, g_notes[0].c_str());
        QVERIFY2(g_notes[0].find("Orientation tag (" + std::to_string(orientation) + ")") !=
                     std::string::npos,
                 g_notes[0].c_str());
    }
}

void ImageOrientationTest::radianceBottomUp() {
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    const int w = 8 + static_cast<int>(rng() % 200), h = 2 + static_cast<int>(rng() % 200);
    std::vector<float> texels(static_cast<std::size_t>(w) * h * 3);
    for (float& t : texels)
        t = std::uniform_real_distribution<float>(0, 4)(rng);
    const std::string topDown = m_dir.filePath("sky.hdr").toStdString();
    auto out = OIIO::ImageOutput::create(topDown);
    QVERIFY(out && out->open(topDown, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)) &&
            out->write_image(OIIO::TypeDesc::FLOAT, texels.data()) && out->close());
    std::string bytes = *readTextFile(topDown);
    const std::string line = "-Y " + std::to_string(h) + " +X " + std::to_string(w);
    const std::size_t at = bytes.find(line);
    QVERIFY(at != std::string::npos);
    bytes[at] = '+'; // the same scanlines, now stored bottom row first
    const std::string bottomUp = m_dir.filePath("sky-up.hdr").toStdString();
    QVERIFY(writeFileAtomically(bottomUp, bytes).ok());

    g_notes.clear();
    const Result<Image> a = readImage(topDown);
    const Result<Image> b = readImage(bottomUp);
    QVERIFY(a.ok() && b.ok());
    QCOMPARE(b->width, w);
    QCOMPARE(b->height, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                if (b->at(x, y, c) != a->at(x, h - 1 - y, c))
                    QFAIL(qPrintable(QString("seed %1: %2x%3, texel (%4, %5)")
                                         .arg(seed)
                                         .arg(w)
                                         .arg(h)
                                         .arg(x)
                                         .arg(y)));
    QCOMPARE(g_notes.size(), std::size_t(1));
    QVERIFY2(g_notes[0].find("sky-up.hdr: flipped top to bottom") != std::string::npos &&
                 g_notes[0].find("+Y") != std::string::npos,
             g_notes[0].c_str());
}

QTEST_GUILESS_MAIN(ImageOrientationTest)
#include "ImageOrientationTest.moc"

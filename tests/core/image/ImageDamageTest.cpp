// Damaged files are refused naming the file, whatever their name says: every format the tool reads,
// written by OpenImageIO from seeded noise at seeded sizes and cut short at a seeded point
// (baseline and progressive JPEGs too, which libjpeg itself only warns about); the format is told
// by the content, so a JPEG named .png reads and text named .png is refused as no image. And every
// reader decodes the bytes it is given: the module is handed a path that does not exist.

#include "ImageModule.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QtTest>
#include <random>

using namespace px;

namespace {

// Writes `w` x `h` x `channels` noise as `file` through OpenImageIO with `attributes`.
bool writeNoise(const std::string& file, int w, int h, int channels, const OIIO::TypeDesc& type,
                const std::vector<std::pair<std::string, std::string>>& attributes,
                std::mt19937& rng) {
    std::vector<float> texels(static_cast<std::size_t>(w) * h * channels);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    for (float& t : texels)
        t = value(rng);
    auto out = OIIO::ImageOutput::create(file);
    if (!out)
        return false;
    OIIO::ImageSpec spec(w, h, channels, type);
    for (const auto& [name, text] : attributes) {
        if (name == "jpeg:progressive")
            spec.attribute(name, 1);
        else
            spec.attribute(name, text);
    }
    return out->open(file, spec) && out->write_image(OIIO::TypeDesc::FLOAT, texels.data()) &&
           out->close();
}

} // namespace

class ImageDamageTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        m_dir.reset(new QTemporaryDir);
        QVERIFY(m_dir->isValid());
    }
    void truncatedFilesRefused_data();
    void truncatedFilesRefused();
    void contentDecidesTheFormat();
    void readersDecodeTheBytesGiven();

private:
    std::string path(const QString& name) const { return m_dir->filePath(name).toStdString(); }
    std::unique_ptr<QTemporaryDir> m_dir;
};

void ImageDamageTest::truncatedFilesRefused_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("channels");
    QTest::addColumn<QString>("type");
    QTest::addColumn<QString>("attribute");
    QTest::addColumn<QString>("value");
    QTest::newRow("jpeg baseline") << "a.jpg" << 3 << "uint8"
                                   << ""
                                   << "";
    QTest::newRow("jpeg progressive") << "a.jpg" << 3 << "uint8"
                                      << "jpeg:progressive"
                                      << "1";
    QTest::newRow("jpeg grey") << "a.jpg" << 1 << "uint8"
                               << ""
                               << "";
    QTest::newRow("png 16-bit") << "a.png" << 3 << "uint16"
                                << ""
                                << "";
    QTest::newRow("tiff none") << "a.tif" << 1 << "uint16"
                               << "compression"
                               << "none";
    QTest::newRow("tiff zip") << "a.tif" << 3 << "uint16"
                              << "compression"
                              << "zip";
    QTest::newRow("tiff lzw") << "a.tif" << 3 << "uint8"
                              << "compression"
                              << "lzw";
    QTest::newRow("tiff float") << "a.tif" << 1 << "float"
                                << "compression"
                                << "zip";
    QTest::newRow("exr zip") << "a.exr" << 3 << "half"
                             << "compression"
                             << "zip";
    QTest::newRow("exr piz") << "a.exr" << 1 << "float"
                             << "compression"
                             << "piz";
    QTest::newRow("exr none") << "a.exr" << 4 << "half"
                              << "compression"
                              << "none";
    QTest::newRow("bmp") << "a.bmp" << 3 << "uint8"
                         << ""
                         << "";
    QTest::newRow("tga") << "a.tga" << 3 << "uint8"
                         << ""
                         << "";
    QTest::newRow("tga rle") << "a.tga" << 4 << "uint8"
                             << "compression"
                             << "rle";
    QTest::newRow("pgm") << "a.pgm" << 1 << "uint8"
                         << ""
                         << "";
    QTest::newRow("ppm 16-bit") << "a.ppm" << 3 << "uint16"
                                << ""
                                << "";
    QTest::newRow("hdr") << "a.hdr" << 3 << "float"
                         << ""
                         << "";
    QTest::newRow("sgi") << "a.sgi" << 3 << "uint8"
                         << ""
                         << "";
    QTest::newRow("sgi rle") << "a.sgi" << 3 << "uint8"
                             << "compression"
                             << "rle";
}

void ImageDamageTest::truncatedFilesRefused() {
    QFETCH(QString, name);
    QFETCH(int, channels);
    QFETCH(QString, type);
    QFETCH(QString, attribute);
    QFETCH(QString, value);
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    const int w = 24 + static_cast<int>(rng() % 300), h = 24 + static_cast<int>(rng() % 300);
    const std::string whole = path("whole." + QFileInfo(name).suffix());
    std::vector<std::pair<std::string, std::string>> attributes;
    if (!attribute.isEmpty())
        attributes.emplace_back(attribute.toStdString(), value.toStdString());
    QVERIFY(writeNoise(whole, w, h, channels, OIIO::TypeDesc(type.toStdString()), attributes, rng));
    const Result<std::string> bytes = readTextFile(whole);
    QVERIFY(bytes.ok());
    QVERIFY2(readImage(whole).ok(), qPrintable(QString("seed %1: the whole file").arg(seed)));
    // Where the texels end: a Targa 2.0's extension area and footer after them are optional, so
    // a file cut there is whole.
    std::size_t end = bytes->size();
    const std::string footer("TRUEVISION-XFILE.\0", 18);
    if (end > 26 && bytes->compare(end - 18, 18, footer) == 0) {
        const auto* f = reinterpret_cast<const unsigned char*>(bytes->data() + end - 26);
        const std::size_t extension =
            f[0] | f[1] << 8 | f[2] << 16 | static_cast<std::size_t>(f[3]) << 24;
        end = extension > 0 ? extension : end - 26;
    }
    // Cut at three seeded points: in the first third (the case), the middle, near the end.
    for (const double from : {0.2, 0.4, 0.9}) {
        const double fraction = from + 0.1 * std::uniform_real_distribution<double>(0, 1)(rng);
        const std::size_t keep = static_cast<std::size_t>(static_cast<double>(end) * fraction);
        const std::string file = path(name);
        QVERIFY(writeFileAtomically(file, bytes->substr(0, keep)).ok());
        const Result<Image> image = readImage(file);
        const QString what = QString("seed %1: %2x%3 cut to %4 of %5 bytes")
                                 .arg(seed)
                                 .arg(w)
                                 .arg(h)
                                 .arg(keep)
                                 .arg(bytes->size());
        QVERIFY2(!image.ok(), qPrintable(what + ": accepted"));
        const QString message = QString::fromStdString(image.error().message);
        QVERIFY2(message.startsWith(QString::fromStdString(file) + ": "), qPrintable(message));
        QVERIFY2(message.count('\n') == 0, qPrintable(message));
        qInfo("%s: %s", qPrintable(what), qPrintable(message));
    }
}

void ImageDamageTest::contentDecidesTheFormat() {
    std::mt19937 rng(7);
    // A JPEG named .png and a TIFF named .jpg read as what they are.
    QVERIFY(writeNoise(path("photo.jpg"), 40, 30, 3, OIIO::TypeDesc::UINT8, {}, rng));
    QVERIFY(writeNoise(path("height.tif"), 40, 30, 1, OIIO::TypeDesc::UINT16, {}, rng));
    const Result<Image> jpeg = readImage(path("photo.jpg"));
    const Result<Image> tiff = readImage(path("height.tif"));
    QVERIFY(jpeg.ok() && tiff.ok());
    QVERIFY(QFile::rename(m_dir->filePath("photo.jpg"), m_dir->filePath("photo.png")));
    QVERIFY(QFile::rename(m_dir->filePath("height.tif"), m_dir->filePath("height.jpg")));
    const Result<Image> jpegAsPng = readImage(path("photo.png"));
    const Result<Image> tiffAsJpg = readImage(path("height.jpg"));
    QVERIFY2(jpegAsPng.ok(), jpegAsPng.ok() ? "" : jpegAsPng.error().message.c_str());
    QVERIFY2(tiffAsJpg.ok(), tiffAsJpg.ok() ? "" : tiffAsJpg.error().message.c_str());
    for (std::size_t i = 0; i < jpeg->pixels.size(); ++i)
        QCOMPARE(jpegAsPng->pixels[i], jpeg->pixels[i]);
    for (std::size_t i = 0; i < tiff->pixels.size(); ++i)
        QCOMPARE(tiffAsJpg->pixels[i], tiff->pixels[i]);
    // Text named .png is no image, said so by name.
    QVERIFY(writeFileAtomically(path("notes.png"), "height maps go here\n").ok());
    const Result<Image> text = readImage(path("notes.png"));
    QVERIFY(!text.ok());
    QVERIFY2(QString::fromStdString(text.error().message)
                 .startsWith(QString::fromStdString(path("notes.png")) +
                             ": not a readable image (its first bytes"),
             text.error().message.c_str());
}

// The decoder gets the bytes and a path that names nothing: it cannot have opened the path, so a
// file swapped for a FIFO (or anything else) after readImage opened it cannot be what is read.
void ImageDamageTest::readersDecodeTheBytesGiven() {
    std::mt19937 rng(11);
    const Result<const ImageModule*> module = imageModule();
    QVERIFY(module.ok());
    for (const char* name :
         {"a.tif", "a.exr", "a.bmp", "a.tga", "a.hdr", "a.sgi", "a.ppm", "a.jpg"}) {
        const std::string file = path(name);
        const bool floats = std::string(name) == "a.hdr" || std::string(name) == "a.exr";
        QVERIFY(writeNoise(file, 33, 21, 3, floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8,
                           {}, rng));
        const Result<Image> reference = readImage(file);
        QVERIFY2(reference.ok(), name);
        ImageSource source;
        source.path = path("gone/nothing-here");
        source.bytes = std::make_shared<const std::string>(*readTextFile(file));
        source.format = OIIO::ImageInput::create(file)->format_name();
        Result<std::unique_ptr<ImageDecoder>> decoder = (*module)->open(source);
        QVERIFY2(decoder.ok(),
                 qPrintable(QString(name) + ": " +
                            QString::fromStdString(decoder.ok() ? "" : decoder.error().message)));
        Image image((*decoder)->header().width, (*decoder)->header().height,
                    (*decoder)->header().channels);
        QVERIFY2((*decoder)->read(image.pixels.data()).ok(), name);
        QCOMPARE(image.pixels.size(), reference->pixels.size());
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            QCOMPARE(image.pixels[i], reference->pixels[i]);
    }
}

QTEST_GUILESS_MAIN(ImageDamageTest)
#include "ImageDamageTest.moc"

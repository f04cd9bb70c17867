// A damaged OpenEXR header is refused before OpenEXR allocates what it claims (found by fuzzing:
// a 584-byte file whose string attribute claimed 1.7 GB).

#include "parallax/image/ImageFile.h"

#include <OpenImageIO/imageio.h>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>
#include <sys/resource.h>

using namespace px;

namespace {

QByteArray validExr(const QTemporaryDir& dir) {
    const std::string file = dir.filePath("valid.exr").toStdString();
    Image image(8, 8, 1);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = static_cast<float>(i) / 64.0f;
    ImageWriteOptions options;
    options.format = PixelFormat::Float;
    if (!writeImage(file, image, options).ok())
        return {};
    QFile f(QString::fromStdString(file));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Offset of the int32 size of the first attribute: magic, version, then "name\0type\0".
int firstSizeOffset(const QByteArray& exr) {
    const int nameEnd = exr.indexOf('\0', 8);
    const int typeEnd = exr.indexOf('\0', nameEnd + 1);
    return typeEnd + 1;
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    QFile f(dir.filePath(name));
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        return {};
    return f.fileName();
}

// A two-part EXR (OpenEXR's multi-part layout: one header per part, then an empty one; the
// parts share their display window).
QByteArray twoPartExr(const QTemporaryDir& dir) {
    const std::string file = dir.filePath("two.exr").toStdString();
    auto out = OIIO::ImageOutput::create(file);
    if (!out || !out->supports("multiimage"))
        return {};
    const OIIO::ImageSpec specs[2] = {OIIO::ImageSpec(4, 4, 1, OIIO::TypeDesc::HALF),
                                      OIIO::ImageSpec(4, 4, 1, OIIO::TypeDesc::FLOAT)};
    const std::vector<float> pixels(16, 0.25f);
    bool ok = out->open(file, 2, specs) && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data());
    ok = ok && out->open(file, specs[1], OIIO::ImageOutput::AppendSubimage) &&
         out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && out->close();
    if (!ok)
        qWarning("%s", out->geterror().c_str());
    QFile f(QString::fromStdString(file));
    return ok && f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

long peakKilobytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

} // namespace

class ExrHeaderTest : public QObject {
    Q_OBJECT

private slots:
    void validFileStillReads();
    void hugeAttributeSizeIsRefusedCheaply();
    void negativeAttributeSizeIsRefused();
    void headerCutShortIsRefused();
    void otherFormatsAreNotInspected();
    void everyPartOfAMultiPartFileIsChecked();
};

void ExrHeaderTest::validFileStillReads() {
    QTemporaryDir dir;
    const QByteArray exr = validExr(dir);
    QVERIFY(exr.size() > 100);
    const auto image = readImage(dir.filePath("valid.exr").toStdString());
    QVERIFY2(image.ok(), image.ok() ? "" : image.error().message.c_str());
    QCOMPARE(image->pixels[63], 63.0f / 64.0f);
}

void ExrHeaderTest::hugeAttributeSizeIsRefusedCheaply() {
    QTemporaryDir dir;
    QByteArray exr = validExr(dir);
    QVERIFY(!exr.isEmpty());
    const int at = firstSizeOffset(exr);
    const char huge[4] = {'\x42', '\x6f', '\x00', '\x69'}; // 0x69006f42 = 1.76e9 bytes
    exr.replace(at, 4, huge, 4);
    const QString path = writeFile(dir, "damaged.exr", exr);
    const long before = peakKilobytes();
    const auto image = readImage(path.toStdString());
    const long grown = peakKilobytes() - before;
    QVERIFY2(grown < 64 * 1024, qPrintable(QString("peak memory grew by %1 kB").arg(grown)));
    QVERIFY(!image.ok());
    const std::string& message = image.error().message;
    QVERIFY2(message.rfind(path.toStdString(), 0) == 0, message.c_str());
    QVERIFY2(message.find("claims 1761636162 bytes") != std::string::npos, message.c_str());
}

void ExrHeaderTest::negativeAttributeSizeIsRefused() {
    QTemporaryDir dir;
    QByteArray exr = validExr(dir);
    QVERIFY(!exr.isEmpty());
    const char negative[4] = {'\xff', '\xff', '\xff', '\xff'};
    exr.replace(firstSizeOffset(exr), 4, negative, 4);
    const auto image = readImage(writeFile(dir, "negative.exr", exr).toStdString());
    QVERIFY(!image.ok());
    QVERIFY2(image.error().message.find("claims -1 bytes") != std::string::npos,
             image.error().message.c_str());
}

void ExrHeaderTest::headerCutShortIsRefused() {
    QTemporaryDir dir;
    const QByteArray exr = validExr(dir);
    QVERIFY(!exr.isEmpty());
    for (const int keep : {6, 20, firstSizeOffset(exr) + 2}) {
        const auto image = readImage(writeFile(dir, "cut.exr", exr.left(keep)).toStdString());
        QVERIFY(!image.ok());
        QVERIFY2(image.error().message.find("OpenEXR header") != std::string::npos,
                 image.error().message.c_str());
    }
}

void ExrHeaderTest::otherFormatsAreNotInspected() {
    // A PNG whose bytes happen to look like anything still gets the image library's own verdict.
    QTemporaryDir dir;
    const std::string png = dir.filePath("x.png").toStdString();
    QVERIFY(writeImage(png, Image(4, 4, 1), {}).ok());
    QVERIFY(readImage(png).ok());
}

void ExrHeaderTest::everyPartOfAMultiPartFileIsChecked() {
    QTemporaryDir dir;
    QByteArray exr = twoPartExr(dir);
    QVERIFY(!exr.isEmpty());
    ImageReadOptions part0;
    part0.page = 0; // a file of several parts is read only by choice (docs/image-files.md)
    QVERIFY(readImage(dir.filePath("two.exr").toStdString(), part0).ok());
    // Corrupt the size of the second part's channel list.
    const QByteArray channels("channels\0chlist\0", 16);
    const int first = exr.indexOf(channels);
    const int second = exr.indexOf(channels, first + 1);
    QVERIFY(first > 0 && second > first);
    const char huge[4] = {'\x00', '\x00', '\x00', '\x40'};
    exr.replace(second + channels.size(), 4, huge, 4);
    const auto image = readImage(writeFile(dir, "two-damaged.exr", exr).toStdString());
    QVERIFY(!image.ok());
    QVERIFY2(image.error().message.find("attribute 'channels' claims 1073741824 bytes") !=
                 std::string::npos,
             image.error().message.c_str());
}

QTEST_APPLESS_MAIN(ExrHeaderTest)
#include "ExrHeaderTest.moc"

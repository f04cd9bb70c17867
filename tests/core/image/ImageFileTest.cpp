// Image writes are atomic: a failure leaves neither half a file nor a changed target.

#include "parallax/image/ImageFile.h"

#include "parallax/io/AtomicWrite.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

using namespace px;

class ImageFileTest : public QObject {
    Q_OBJECT

private slots:
    void roundTrip16Bit();
    void failedWriteKeepsPreviousFile();
    void missingFolderIsAnError();
    void noTemporaryFilesRemain();
    void textFilesAreAtomicToo();
};

void ImageFileTest::roundTrip16Bit() {
    QTemporaryDir dir;
    Image image(3, 2, 2);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = static_cast<float>(i * 1000) / 65535.0f;
    const std::string file = dir.filePath("a.png").toStdString();
    ImageWriteOptions options;
    options.format = PixelFormat::UInt16;
    QVERIFY(writeImage(file, image, options).ok());
    const auto back = readImage(file);
    QVERIFY(back.ok());
    QCOMPARE(back->channels, 2);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        QVERIFY(std::abs(back->pixels[i] - image.pixels[i]) < 1e-6f);
}

void ImageFileTest::failedWriteKeepsPreviousFile() {
    QTemporaryDir dir;
    const std::string file = dir.filePath("keep.png").toStdString();
    Image first(2, 2, 1);
    first.pixels = {0.0f, 1.0f, 1.0f, 0.0f};
    QVERIFY(writeImage(file, first, {}).ok());
    ImageWriteOptions floatPng;
    floatPng.format = PixelFormat::Float; // PNG cannot hold float: refused before touching anything
    const Status refused = writeImage(file, Image(4, 4, 1), floatPng);
    QVERIFY(!refused.ok());
    QVERIFY(refused.error().message.find("keep.png") != std::string::npos);
    const auto back = readImage(file);
    QVERIFY(back.ok());
    QCOMPARE(back->width, 2);
    QCOMPARE(back->pixels[1], 1.0f);
}

void ImageFileTest::missingFolderIsAnError() {
    QTemporaryDir dir;
    const std::string file = dir.filePath("no/such/folder/x.png").toStdString();
    const Status s = writeImage(file, Image(2, 2, 1), {});
    QVERIFY(!s.ok());
    QVERIFY(s.error().message.find("x.png") != std::string::npos);
}

void ImageFileTest::noTemporaryFilesRemain() {
    QTemporaryDir dir;
    QVERIFY(
        writeImage(dir.filePath("a.exr").toStdString(), Image(2, 2, 3), {PixelFormat::Half, false})
            .ok());
    QVERIFY(writeTextFile(dir.filePath("b.csv").toStdString(), "x\n").ok());
    const QStringList files = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden);
    QCOMPARE(files, QStringList({"a.exr", "b.csv"}));
}

void ImageFileTest::textFilesAreAtomicToo() {
    QTemporaryDir dir;
    const std::string file = dir.filePath("t.txt").toStdString();
    QVERIFY(writeTextFile(file, "first").ok());
    QVERIFY(!writeTextFile(dir.filePath("missing/t.txt").toStdString(), "x").ok());
    QCOMPARE(readTextFile(file).value(), std::string("first"));
    QVERIFY(writeTextFile(file, "second").ok());
    QCOMPARE(readTextFile(file).value(), std::string("second"));
}

QTEST_APPLESS_MAIN(ImageFileTest)
#include "ImageFileTest.moc"

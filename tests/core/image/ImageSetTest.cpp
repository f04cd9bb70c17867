// A numbered set of images written as one: names, every frame written, and on a failure the
// previous set untouched and no temporary left behind.

#include "parallax/image/ImageSet.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

using namespace px;

class ImageSetTest : public QObject {
    Q_OBJECT

private slots:
    void names();
    void writesEveryFrame();
    void failureKeepsThePreviousSet();
};

void ImageSetTest::names() {
    const std::vector<std::string> three = numberedFiles("out/spin.png", 3);
    QCOMPARE(three.size(), std::size_t(3));
    QCOMPARE(QString::fromStdString(three[0]), QString("out/spin-000.png"));
    QCOMPARE(QString::fromStdString(three[2]), QString("out/spin-002.png"));
    QCOMPARE(QString::fromStdString(numberedFiles("spin", 1001)[1000]), QString("spin-1000.png"));
}

namespace {
Image grey(float v) {
    Image image(8, 4, 3);
    std::fill(image.pixels.begin(), image.pixels.end(), v);
    return image;
}
} // namespace

void ImageSetTest::writesEveryFrame() {
    QTemporaryDir dir;
    const std::vector<std::string> files = numberedFiles(dir.filePath("t.png").toStdString(), 4);
    QVERIFY(writeImageSet(files, [](int i) { return Result<Image>(grey(0.2f * i)); }, {}).ok());
    for (int i = 0; i < 4; ++i) {
        Result<Image> back = readImage(files[static_cast<std::size_t>(i)]);
        QVERIFY(back.ok());
        QVERIFY(std::abs(back->at(3, 2, 0) - 0.2f * i) < 0.5f / 255.0f);
    }
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 4);
}

void ImageSetTest::failureKeepsThePreviousSet() {
    QTemporaryDir dir;
    const std::vector<std::string> files = numberedFiles(dir.filePath("t.png").toStdString(), 3);
    QVERIFY(writeImageSet(files, [](int) { return Result<Image>(grey(0.0f)); }, {}).ok());
    const Status failed = writeImageSet(files,
                                        [](int i) {
                                            return i < 2 ? Result<Image>(grey(1.0f))
                                                         : Result<Image>(Error{"frame 2 failed"});
                                        },
                                        {});
    QVERIFY(!failed.ok());
    QCOMPARE(QString::fromStdString(failed.error().message), QString("frame 2 failed"));
    for (const std::string& f : files) {
        Result<Image> back = readImage(f);
        QVERIFY(back.ok());
        QCOMPARE(back->at(0, 0, 0), 0.0f); // the previous frames, untouched
    }
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 3); // no temporary
}

QTEST_APPLESS_MAIN(ImageSetTest)
#include "ImageSetTest.moc"

// Ordinary mistakes: an output that is an input, a folder as output, a missing folder, a header
// that claims more than the file or the machine holds. Each is refused before any work with a
// message naming the user's file and the problem, and the folder is left byte for byte as it was.

#include "FaultSupport.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace px::faults;

class FaultInputsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { printTally("inputs"); }
    void outputIsAnInput_data();
    void outputIsAnInput();
    void folderAsOutput_data();
    void folderAsOutput();
    void missingFolder_data();
    void missingFolder();
    void oversizedHeader_data();
    void oversizedHeader();
    void damagedPng_data();
    void damagedPng();

private:
    QString m_dir;
    QTemporaryDir m_temp;
};

void FaultInputsTest::initTestCase() {
    QVERIFY(m_temp.isValid());
    m_dir = m_temp.path();
    QCOMPARE(runCli(m_dir, {"sample", "noise", "--size", "32", "--out", "h.png"}).status, 0);
    QVERIFY(QFile::link(m_dir + "/h.png", m_dir + "/symlink.png"));
    QVERIFY(::link(QString(m_dir + "/h.png").toLocal8Bit(),
                   QString(m_dir + "/hard.png").toLocal8Bit()) == 0);
    QDir(m_dir).mkdir("folder.png");
    QDir(m_dir).mkdir("sub");
    QDir(m_dir).mkdir("folder.csv");
}

void FaultInputsTest::outputIsAnInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("file");
    const QString same = "--out names the same file as --height";
    for (const char* kind : {"normal", "cone", "relaxed-cone", "pyramid"})
        QTest::newRow(kind) << QStringList{"bake", kind, "--height", "h.png", "--out", "h.png"}
                            << "h.png";
    QTest::newRow("hard link") << QStringList{"bake",  "cone",  "--height",
                                              "h.png", "--out", "hard.png"}
                               << "hard.png";
    QTest::newRow("symbolic link")
        << QStringList{"bake", "normal", "--height", "symlink.png", "--out", "./h.png"}
        << "./h.png";
    QTest::newRow("trace") << QStringList{"trace", "--height", "h.png", "--out", "h.png"}
                           << "h.png";
    QTest::newRow("render") << QStringList{"render", "--height", "h.png", "--out", "h.png"}
                            << "h.png";
    QTest::newRow("render albedo")
        << QStringList{"render",   "--height", "h.png",        "--albedo",
                       "hard.png", "--out",    "sub/../hard.png"}
        << "hard.png";
    QTest::newRow("bench --out") << QStringList{"bench", "--height", "h.png", "--out", "h.png"}
                                 << "h.png";
    QTest::newRow("bench --plot") << QStringList{"bench", "--height", "h.png", "--out",
                                                 "o.csv", "--plot",   "h.png"}
                                  << "h.png";
}

void FaultInputsTest::outputIsAnInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, file);
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, file,
                            "names the same file as --(height|albedo)[^\\n]*refusing to overwrite "
                            "an input");
}

void FaultInputsTest::folderAsOutput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::newRow("bake") << QStringList{"bake",  "cone",  "--height",
                                         "h.png", "--out", "folder.png"};
    QTest::newRow("sample") << QStringList{"sample", "noise", "--out", "folder.png"};
    QTest::newRow("trace") << QStringList{"trace", "--height", "h.png", "--out", "folder.csv"};
    QTest::newRow("render") << QStringList{"render", "--height", "h.png", "--out", "folder.png"};
    QTest::newRow("bench") << QStringList{"bench", "--height", "h.png", "--out", "folder.csv"};
}

void FaultInputsTest::folderAsOutput() {
    QFETCH(QStringList, args);
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, "folder.", "--out is a folder; give a file name");
}

void FaultInputsTest::missingFolder_data() {
    QTest::addColumn<QStringList>("args");
    QTest::newRow("bake") << QStringList{"bake",  "normal", "--height",
                                         "h.png", "--out",  "no/x.png"};
    QTest::newRow("sample") << QStringList{"sample", "bricks", "--out", "no/x.png"};
    QTest::newRow("trace") << QStringList{"trace", "--height", "h.png", "--out", "no/x.png"};
    // Checked before measuring, not after.
    QTest::newRow("bench --plot") << QStringList{"bench", "--height", "h.png",   "--out",
                                                 "o.csv", "--plot",   "no/x.png"};
    QTest::newRow("stability") << QStringList{"stability", "--case", "flat-0", "--csv", "no/x.png"};
}

void FaultInputsTest::missingFolder() {
    QFETCH(QStringList, args);
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, "no/x.png",
                            "cannot create the file: the folder no does not exist");
}

void FaultInputsTest::oversizedHeader_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("extra");
    QTest::addColumn<QString>("reason");
    const QString tooBig = "which a file of [0-9]+ bytes cannot hold";
    // The PNG of the issue: 16384 x 16384 16-bit RGBA in a few dozen bytes.
    QTest::newRow("png 16384") << "png16384.png" << QStringList{} << tooBig;
    QTest::newRow("png 100000 --allow-large")
        << "png100000.png" << QStringList{"--allow-large"} << tooBig;
    QTest::newRow("png 100000") << "png100000.png" << QStringList{}
                                << "larger than the limit of 16384 texels a side";
}

void FaultInputsTest::oversizedHeader() {
    QFETCH(QString, file);
    QFETCH(QStringList, extra);
    QFETCH(QString, reason);
    // A real 2x2 16-bit RGBA PNG with its header's size patched (CRC recomputed by the CLI's own
    // reader being lenient is not relied on: the core.image.ImageClaim test covers TIFF, JPEG and
    // EXR the same way).
    const int side = file.contains("16384") ? 16384 : 100000;
    QCOMPARE(runCli(m_dir, {"sample", "noise", "--size", "2", "--bits", "16", "--out", "src.png"})
                 .status,
             0);
    QFile src(m_dir + "/src.png");
    QVERIFY(src.open(QIODevice::ReadOnly));
    QByteArray bytes = src.readAll();
    src.close();
    QFile::remove(m_dir + "/src.png");
    for (int at : {16, 20})
        for (int i = 0; i < 4; ++i)
            bytes[at + i] = static_cast<char>((side >> (24 - 8 * i)) & 0xff);
    quint32 crc = 0xffffffffu;
    for (int i = 12; i < 29; ++i) {
        crc ^= static_cast<unsigned char>(bytes[i]);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    crc = ~crc;
    for (int i = 0; i < 4; ++i)
        bytes[29 + i] = static_cast<char>((crc >> (24 - 8 * i)) & 0xff);
    QFile out(m_dir + "/" + file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    out.close();
    PX_EXPECT_CLEAN_FAILURE(m_dir,
                            QStringList({"trace", "--height", file, "--out", "t.csv"}) + extra, {},
                            1, file, reason);
}

void FaultInputsTest::damagedPng_data() {
    QTest::addColumn<int>("keep"); // bytes kept (-1: all, one flipped in the image data)
    QTest::addColumn<QString>("reason");
    QTest::newRow("cut in the header") << 20 << "the file is truncated";
    QTest::newRow("cut in the data") << 300 << "the file is truncated \\(its IDAT chunk runs past";
    QTest::newRow("cut before IEND") << -2 << "without the PNG's IEND chunk";
    QTest::newRow("a flipped byte") << -1 << "the file is damaged \\(its IDAT chunk does not match";
}

// One message of the project's, never libpng's own "libpng error:" line on stderr.
void FaultInputsTest::damagedPng() {
    QFETCH(int, keep);
    QFETCH(QString, reason);
    QCOMPARE(runCli(m_dir, {"sample", "noise", "--size", "64", "--out", "whole.png"}).status, 0);
    QFile whole(m_dir + "/whole.png");
    QVERIFY(whole.open(QIODevice::ReadOnly));
    QByteArray bytes = whole.readAll();
    whole.close();
    QFile::remove(m_dir + "/whole.png");
    if (keep >= 0)
        bytes.truncate(keep);
    else if (keep == -2)
        bytes.chop(12); // the IEND chunk
    else
        bytes[bytes.indexOf("IDAT") + 40] =
            static_cast<char>(bytes[bytes.indexOf("IDAT") + 40] ^ 0x55);
    QFile out(m_dir + "/damaged.png");
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    out.close();
    PX_EXPECT_CLEAN_FAILURE(m_dir,
                            QStringList({"trace", "--height", "damaged.png", "--out", "t.csv"}), {},
                            1, "damaged.png", reason);
    const CliRun run = runCli(m_dir, {"trace", "--height", "damaged.png", "--out", "t.csv"});
    QVERIFY2(!run.output.contains("libpng"), qPrintable(run.output));
    QCOMPARE(run.output.count("error:"), 1);
    QFile::remove(m_dir + "/damaged.png");
}

QTEST_GUILESS_MAIN(FaultInputsTest)
#include "FaultInputsTest.moc"

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
    QMap<QString, QByteArray> m_sources; // by extension: the images the cases patch
    QTemporaryDir m_temp;
};

void FaultInputsTest::initTestCase() {
    QVERIFY(m_temp.isValid());
    m_dir = m_temp.path();
    QVERIFY(writeSample(m_dir + "/h.png", "noise", 32));
    // The smallest real image of each format the commands read (as `sample` writes them: 16-bit
    // PNG and TIFF, float EXR, 8-bit JPEG) and a whole PNG to damage; made once, patched per case.
    for (const auto& [ext, bits] :
         {std::pair{"png", 16}, {"tif", 16}, {"exr", 32}, {"jpg", 8}, {"whole.png", 16}}) {
        const QString path = m_dir + "/src." + ext;
        QVERIFY(writeSample(path, "noise", QString(ext) == "whole.png" ? 64 : 8, 1, bits));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        m_sources.insert(ext, file.readAll());
        file.close();
        QVERIFY(file.remove());
    }
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
        << QStringList{"render",   "--height", "h.png",          "--albedo",
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

namespace {

void putBig32(QByteArray& bytes, int at, quint32 value) {
    for (int i = 0; i < 4; ++i)
        bytes[at + i] = static_cast<char>((value >> (24 - 8 * i)) & 0xff);
}

void putLittle32(QByteArray& bytes, int at, quint32 value) {
    for (int i = 0; i < 4; ++i)
        bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xff);
}

quint32 big32(const QByteArray& bytes, int at) {
    quint32 value = 0;
    for (int i = 0; i < 4; ++i)
        value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
    return value;
}

// PNG's CRC-32 of `count` bytes from `from`.
quint32 crc32(const QByteArray& bytes, int from, int count) {
    quint32 crc = 0xffffffffu;
    for (int i = from; i < from + count; ++i) {
        crc ^= static_cast<unsigned char>(bytes[i]);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

quint32 little(const QByteArray& bytes, int at, int size) {
    quint32 value = 0;
    for (int i = size - 1; i >= 0; --i)
        value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
    return value;
}

// A real small image with its header's width and height set to `side` (checksums recomputed
// where the format has them): what a damaged or hostile file looks like to the reader.
bool claimSide(QByteArray& bytes, const QString& ext, quint32 side) {
    if (ext == "png") {
        putBig32(bytes, 16, side); // IHDR width, height, then its CRC over type and data
        putBig32(bytes, 20, side);
        putBig32(bytes, 29, crc32(bytes, 12, 17));
        return true;
    }
    if (ext == "jpg") { // the SOF0 segment: height, width as 16 bits
        const int sof = bytes.indexOf("\xff\xc0");
        if (sof < 0 || side > 65535)
            return false;
        bytes[sof + 5] = bytes[sof + 7] = static_cast<char>(side >> 8);
        bytes[sof + 6] = bytes[sof + 8] = static_cast<char>(side & 0xff);
        return true;
    }
    if (ext == "tif") { // little-endian: ImageWidth and ImageLength in the first IFD, as LONG
        if (!bytes.startsWith("II"))
            return false;
        const int ifd = static_cast<int>(little(bytes, 4, 4));
        const int entries = static_cast<int>(little(bytes, ifd, 2));
        int patched = 0;
        for (int e = 0; e < entries; ++e) {
            const int at = ifd + 2 + 12 * e;
            const quint32 tag = little(bytes, at, 2);
            if (tag == 256 || tag == 257) {
                bytes[at + 2] = 4; // type LONG, count 1, the value
                bytes[at + 3] = 0;
                putLittle32(bytes, at + 4, 1);
                putLittle32(bytes, at + 8, side);
                ++patched;
            }
        }
        return patched == 2;
    }
    // OpenEXR: the box2i data and display windows, (xMin, yMin, xMax, yMax). Zeros after it
    // stand for the line offset table, so that OpenEXR opens it (without them it refuses the
    // file itself) and the claim meets the project's check.
    for (const QByteArray& attr : {QByteArray("dataWindow"), QByteArray("displayWindow")}) {
        const int at = bytes.indexOf(attr + QByteArray("\0box2i\0", 7));
        if (at < 0)
            return false;
        const int box = at + static_cast<int>(attr.size()) + 7 + 4; // past name, type, size
        putLittle32(bytes, box + 8, side - 1);
        putLittle32(bytes, box + 12, side - 1);
    }
    bytes.append(QByteArray(static_cast<int>(side) * 8, '\0'));
    return true;
}

} // namespace

void FaultInputsTest::oversizedHeader_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("extra");
    QTest::addColumn<QString>("reason");
    const QString tooBig = "which a file of [0-9]+ bytes cannot hold";
    const QString tooWide = "larger than the limit of 16384 texels a side";
    // The issue's PNG: 16384 x 16384 16-bit in a few dozen bytes; then the other formats the
    // commands read, each claiming the largest size allowed by default and a huge one.
    for (const char* ext : {"png", "tif", "exr", "jpg"}) {
        const QString at16384 = QString("%1 16384").arg(ext);
        QTest::newRow(qPrintable(at16384))
            << QString("claim16384.%1").arg(ext) << QStringList{} << tooBig;
        const int huge = QString(ext) == "jpg" ? 65500 : 100000; // JPEG sizes are 16-bit
        QTest::newRow(qPrintable(QString("%1 %2 --allow-large").arg(ext).arg(huge)))
            << QString("claim%1.%2").arg(huge).arg(ext) << QStringList{"--allow-large"} << tooBig;
        QTest::newRow(qPrintable(QString("%1 %2").arg(ext).arg(huge)))
            << QString("claim%1.%2").arg(huge).arg(ext) << QStringList{} << tooWide;
    }
}

void FaultInputsTest::oversizedHeader() {
    QFETCH(QString, file);
    QFETCH(QStringList, extra);
    QFETCH(QString, reason);
    const QString ext = QFileInfo(file).suffix();
    const quint32 side = QFileInfo(file).baseName().mid(5).toUInt();
    QByteArray bytes = m_sources.value(ext);
    QVERIFY2(claimSide(bytes, ext, side), qPrintable(file));
    QFile out(m_dir + "/" + file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    out.close();
    PX_EXPECT_CLEAN_FAILURE(m_dir,
                            QStringList({"trace", "--height", file, "--out", "t.csv"}) + extra, {},
                            1, file, reason);
    QFile::remove(out.fileName());
}

void FaultInputsTest::damagedPng_data() {
    // bytes kept (-1: all, one flipped in the image data; -3: the same with its checksum
    // fixed, which only decoding the data finds)
    QTest::addColumn<int>("keep");
    QTest::addColumn<QString>("reason");
    QTest::newRow("cut in the header") << 20 << "the file is truncated";
    QTest::newRow("cut in the data") << 300 << "the file is truncated \\(its IDAT chunk runs past";
    QTest::newRow("cut before IEND") << -2 << "without the PNG's IEND chunk";
    QTest::newRow("a flipped byte") << -1 << "the file is damaged \\(its IDAT chunk does not match";
    QTest::newRow("a flipped byte, checksum fixed")
        << -3 << "the file is damaged \\(its image data does not decode: IDAT: ";
}

// One message of the project's, never libpng's own "libpng error:" line on stderr.
void FaultInputsTest::damagedPng() {
    QFETCH(int, keep);
    QFETCH(QString, reason);
    QByteArray bytes = m_sources.value("whole.png");
    if (keep >= 0)
        bytes.truncate(keep);
    else if (keep == -2)
        bytes.chop(12); // the IEND chunk
    else
        bytes[bytes.indexOf("IDAT") + 40] =
            static_cast<char>(bytes[bytes.indexOf("IDAT") + 40] ^ 0x55);
    if (keep == -3) { // the IDAT chunk's CRC over its type and data, as a careful forger would
        const int type = static_cast<int>(bytes.indexOf("IDAT"));
        const int length = static_cast<int>(big32(bytes, type - 4));
        putBig32(bytes, type + 4 + length, crc32(bytes, type, length + 4));
    }
    QFile out(m_dir + "/damaged.png");
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    out.close();
    QString said;
    PX_EXPECT_CLEAN_FAILURE_SAYING(
        m_dir, QStringList({"trace", "--height", "damaged.png", "--out", "t.csv"}), {}, 1,
        "damaged.png", reason, said);
    QVERIFY2(!said.contains("libpng"), qPrintable(said));
    QCOMPARE(said.count("error:"), 1);
    QFile::remove(m_dir + "/damaged.png");
}

QTEST_GUILESS_MAIN(FaultInputsTest)
#include "FaultInputsTest.moc"

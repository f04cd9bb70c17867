// Headers that claim more than the file can hold or the machine can allocate are refused before
// any pixel memory is taken (the read runs with too little address space for the pixels): PNG,
// JPEG, TIFF and EXR, each written small and then patched.

#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cstdint>
#include <fstream>
#include <sys/resource.h>
#include <unistd.h>

using namespace px;

namespace {

std::uint32_t crc32(const std::string& bytes, std::size_t from, std::size_t count) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = from; i < from + count; ++i) {
        crc ^= static_cast<unsigned char>(bytes[i]);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void putBig32(std::string& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i)
        bytes[at + i] = static_cast<char>((value >> (24 - 8 * i)) & 0xff);
}

void putLittle32(std::string& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i)
        bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xff);
}

// Limits the process's address space to what it has now plus `headroom` while it lives: an
// allocation beyond that fails at once, however lazily the system would have backed it. Not under
// AddressSanitizer, whose shadow memory needs terabytes of address space.
class AddressSpaceCap {
public:
    explicit AddressSpaceCap(long long headroom) {
#if !defined(__SANITIZE_ADDRESS__)
        long pages = 0;
        std::ifstream("/proc/self/statm") >> pages;
        getrlimit(RLIMIT_AS, &m_old);
        rlimit capped = m_old;
        capped.rlim_cur = static_cast<rlim_t>(pages) * static_cast<rlim_t>(sysconf(_SC_PAGESIZE)) +
                          static_cast<rlim_t>(headroom);
        m_set = setrlimit(RLIMIT_AS, &capped) == 0;
#else
        (void)headroom;
#endif
    }
    ~AddressSpaceCap() {
        if (m_set)
            setrlimit(RLIMIT_AS, &m_old);
    }
    AddressSpaceCap(const AddressSpaceCap&) = delete;
    AddressSpaceCap& operator=(const AddressSpaceCap&) = delete;

private:
    rlimit m_old{};
    bool m_set = false;
};

} // namespace

class ImageClaimTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        m_dir.reset(new QTemporaryDir);
        QVERIFY(m_dir->isValid());
    }
    void hugeClaimsRefusedAtOnce_data();
    void hugeClaimsRefusedAtOnce();
    void flatImagesPass_data();
    void flatImagesPass();

private:
    // A small real image of `extension`, written by the project's own writer.
    std::string smallImage(const std::string& name, int channels, PixelFormat format) {
        const std::string file = m_dir->filePath(QString::fromStdString(name)).toStdString();
        ImageWriteOptions options;
        options.format = format;
        Image image(8, 8, channels);
        if (!writeImage(file, image, options).ok())
            return {};
        return *readTextFile(file);
    }
    std::unique_ptr<QTemporaryDir> m_dir;
};

void ImageClaimTest::hugeClaimsRefusedAtOnce_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("side");
    QTest::addColumn<QString>("reason");
    // The case: 16384 x 16384 16-bit RGBA from a 74-byte-scale PNG (4.3 GB as float).
    QTest::newRow("png 16384") << "a.png" << 16384 << "which a file of [0-9]+ bytes cannot hold";
    QTest::newRow("png 100000") << "b.png" << 100000 << "which a file of [0-9]+ bytes cannot hold";
    QTest::newRow("jpeg 65500") << "c.jpg" << 65500 << "which a file of [0-9]+ bytes cannot hold";
    // TIFF and EXR this large: refused by the image library's own limits on open (OIIO's
    // imagesize_MB, OpenEXR's offset table past the end), before any pixel memory; smaller
    // claims meet the file-size bound (faults.Inputs) and the memory check.
    const QString memory = "more than the [0-9.]+ GB available";
    QTest::newRow("tiff 1000000") << "d.tif" << 1000000
                                  << "(" + memory + "|exceeds \"limits:imagesize_MB\")";
    QTest::newRow("exr 1000000") << "e.exr" << 1000000 << "(" + memory + "|Unexpected end of file)";
}

void ImageClaimTest::hugeClaimsRefusedAtOnce() {
    QFETCH(QString, name);
    QFETCH(int, side);
    QFETCH(QString, reason);
    const std::string ext = QFileInfo(name).suffix().toStdString();
    const auto s = static_cast<std::uint32_t>(side);
    std::string bytes;
    if (ext == "png") {
        bytes = smallImage("src.png", 4, PixelFormat::UInt16);
        putBig32(bytes, 16, s); // IHDR width, height and its CRC
        putBig32(bytes, 20, s);
        putBig32(bytes, 29, crc32(bytes, 12, 17));
    } else if (ext == "jpg") {
        bytes = smallImage("src.jpg", 3, PixelFormat::UInt8);
        const std::size_t sof = bytes.find("\xff\xc0");
        QVERIFY(sof != std::string::npos);
        bytes[sof + 5] = bytes[sof + 7] = static_cast<char>(s >> 8); // height, width (16-bit)
        bytes[sof + 6] = bytes[sof + 8] = static_cast<char>(s & 0xff);
    } else if (ext == "tif") {
        bytes = smallImage("src.tif", 1, PixelFormat::UInt16);
        QVERIFY(bytes.substr(0, 2) == "II"); // little-endian: patch ImageWidth/ImageLength
        const std::uint32_t ifd =
            static_cast<unsigned char>(bytes[4]) | static_cast<unsigned char>(bytes[5]) << 8 |
            static_cast<unsigned char>(bytes[6]) << 16 | static_cast<unsigned char>(bytes[7]) << 24;
        const int count = static_cast<unsigned char>(bytes[ifd]) | bytes[ifd + 1] << 8;
        for (int e = 0; e < count; ++e) {
            const std::size_t at = ifd + 2 + 12 * e;
            const int tag = static_cast<unsigned char>(bytes[at]) |
                            static_cast<unsigned char>(bytes[at + 1]) << 8;
            if (tag == 256 || tag == 257) {
                bytes[at + 2] = 4; // type LONG, count 1, the value
                bytes[at + 3] = 0;
                putLittle32(bytes, at + 8, s);
            }
        }
    } else {
        bytes = smallImage("src.exr", 1, PixelFormat::Float);
        for (const std::string attr : {"dataWindow", "displayWindow"}) {
            const std::size_t at = bytes.find(attr + std::string("\0box2i\0", 7));
            QVERIFY(at != std::string::npos);
            const std::size_t box = at + attr.size() + 7 + 4; // past the name, type and size
            putLittle32(bytes, box + 8, s - 1);               // xMax, yMax
            putLittle32(bytes, box + 12, s - 1);
        }
    }
    const std::string file = m_dir->filePath(name).toStdString();
    QVERIFY(writeFileAtomically(file, bytes).ok());

    ImageReadOptions options;
    options.maxSide = 1 << 30; // as --allow-large: the claim itself must be judged
    Result<Image> image = Image{};
    {
        // Every claim here is 4 GB of pixels or more: with 2 GB more address space than the
        // process has, taking pixel memory for it fails, and the message would say so instead.
        const AddressSpaceCap cap(2LL << 30);
        image = readImage(file, options);
    }
    QVERIFY(!image.ok());
    const QString message = QString::fromStdString(image.error().message);
    QVERIFY2(message.startsWith(QString::fromStdString(file) + ": "), qPrintable(message));
    QVERIFY2(message.contains(QRegularExpression(reason)), qPrintable(message));
    qInfo("%s: refused: %s", qPrintable(name), qPrintable(message));
}

// The file-size bound must not refuse a real file: a flat image is the best case of every
// compression, so each format's writer at its default compression stays within the bound.
void ImageClaimTest::flatImagesPass_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("format");
    QTest::addColumn<int>("channels");
    QTest::newRow("png 16-bit") << "f.png" << static_cast<int>(PixelFormat::UInt16) << 1;
    QTest::newRow("png 8-bit rgba") << "f.png" << static_cast<int>(PixelFormat::UInt8) << 4;
    QTest::newRow("tiff 16-bit") << "f.tif" << static_cast<int>(PixelFormat::UInt16) << 1;
    QTest::newRow("exr float") << "f.exr" << static_cast<int>(PixelFormat::Float) << 1;
    QTest::newRow("exr half rgba") << "f.exr" << static_cast<int>(PixelFormat::Half) << 4;
    QTest::newRow("jpeg") << "f.jpg" << static_cast<int>(PixelFormat::UInt8) << 3;
}

void ImageClaimTest::flatImagesPass() {
    QFETCH(QString, name);
    QFETCH(int, format);
    QFETCH(int, channels);
    const std::string file = m_dir->filePath(name).toStdString();
    ImageWriteOptions options;
    options.format = static_cast<PixelFormat>(format);
    const Image flat(2048, 2048, channels);
    QVERIFY(writeImage(file, flat, options).ok());
    const Result<Image> image = readImage(file);
    QVERIFY2(image.ok(), image.ok() ? "" : image.error().message.c_str());
    qInfo("%s: %lld bytes for %d channel(s) of 2048 x 2048", qPrintable(name),
          static_cast<long long>(QFileInfo(QString::fromStdString(file)).size()), channels);
}

QTEST_GUILESS_MAIN(ImageClaimTest)
#include "ImageClaimTest.moc"

// Headers that claim more than the file can hold or the process can allocate are refused before
// any pixel memory is taken (the read runs with too little address space for the pixels): PNG,
// JPEG, TIFF and EXR written small and then patched; BMP, Targa, PNM, Radiance HDR, SGI and DDS
// headers written by hand with a few bytes of data; a real file whose float copy exceeds the
// process's RLIMIT_AS. And the bound never refuses a real file: flat images, and palette PNGs of
// every bit depth as optimisers write them.

#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cstdint>
#include <fstream>
#include <png.h>
#include <random>
#include <sys/resource.h>
#include <unistd.h>
#include <zlib.h>

using namespace px;

namespace {

std::uint32_t crc32(const std::string& bytes, std::size_t from, std::size_t count) {
    return static_cast<std::uint32_t>(
        ::crc32(0, reinterpret_cast<const Bytef*>(bytes.data() + from), static_cast<uInt>(count)));
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
    void lyingHeadersRefusedBeforeDecoding_data();
    void lyingHeadersRefusedBeforeDecoding();
    void palettePngsPass();
    void memoryLimitOfTheProcess();

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
    const QString memory = "more than the [0-9.]+ GB available to this process";
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

namespace {

std::string little16(std::uint32_t v) {
    return {static_cast<char>(v & 0xff), static_cast<char>(v >> 8 & 0xff)};
}
std::string little32(std::uint32_t v) {
    return little16(v & 0xffff) + little16(v >> 16);
}
std::string big16(std::uint32_t v) {
    return {static_cast<char>(v >> 8 & 0xff), static_cast<char>(v & 0xff)};
}

// A header of `kind` claiming w x h texels, then `data` bytes of noise: what a truncated or
// lying file of that format looks like to a reader.
std::string lyingFile(const std::string& kind, std::uint32_t w, std::uint32_t h, std::size_t data,
                      std::mt19937& rng) {
    std::string b;
    if (kind == "bmp") { // BITMAPINFOHEADER, 24-bit, uncompressed: 118 bytes with 64 of data
        b = "BM" + little32(54 + data) + little32(0) + little32(54) + little32(40) + little32(w) +
            little32(h) + little16(1) + little16(24) + little32(0) + little32(0) + little32(2835) +
            little32(2835) + little32(0) + little32(0);
    } else if (kind == "tga" || kind == "tga-rle") { // true colour, 24-bit, top-left origin
        b = std::string{0, 0, static_cast<char>(kind == "tga" ? 2 : 10), 0, 0, 0, 0, 0, 0, 0,
                        0, 0} +
            little16(w) + little16(h) + std::string{24, 0x20};
    } else if (kind == "pgm") {
        b = "P5\n# lying\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    } else if (kind == "ppm16") {
        b = "P6\n" + std::to_string(w) + " " + std::to_string(h) + "\n65535\n";
    } else if (kind == "pbm") {
        b = "P4\n" + std::to_string(w) + " " + std::to_string(h) + "\n";
    } else if (kind == "hdr") {
        b = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " +
            std::to_string(w) + "\n";
    } else if (kind == "sgi" || kind == "sgi-rle") { // 8-bit RGB
        b = big16(474) + std::string{static_cast<char>(kind == "sgi" ? 0 : 1), 1} + big16(3) +
            big16(w) + big16(h) + big16(3);
        b.resize(512, '\0');
    } else if (kind == "dds") { // DXT5 (BC3), as a normal map is stored
        b = "DDS " + little32(124) + little32(0x1007) + little32(h) + little32(w) + little32(0) +
            little32(0) + little32(0) + std::string(44, '\0') + little32(32) + little32(4) +
            "DXT5" + std::string(20, '\0') + little32(0x1000) + std::string(16, '\0');
    }
    for (std::size_t i = 0; i < data; ++i)
        b.push_back(static_cast<char>(rng()));
    return b;
}

} // namespace

void ImageClaimTest::lyingHeadersRefusedBeforeDecoding_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("maxSide");
    // The cases: a 118-byte BMP claiming 16384², a 34-byte RLE Targa, PGM, SGI, HDR;
    // a DDS named .png (the content decides: it is judged as the DDS it is).
    QTest::newRow("bmp") << "bmp"
                         << "lie.bmp" << 16384;
    QTest::newRow("tga") << "tga"
                         << "lie.tga" << 16384;
    QTest::newRow("tga rle") << "tga-rle"
                             << "lie.tga" << 16384;
    QTest::newRow("pgm") << "pgm"
                         << "lie.pgm" << 16384;
    QTest::newRow("ppm 16-bit") << "ppm16"
                                << "lie.ppm" << 16384;
    QTest::newRow("pbm") << "pbm"
                         << "lie.pbm" << 16384;
    QTest::newRow("hdr") << "hdr"
                         << "lie.hdr" << 16384;
    QTest::newRow("sgi") << "sgi"
                         << "lie.sgi" << 16384;
    QTest::newRow("sgi rle") << "sgi-rle"
                             << "lie.rgb" << 16384;
    QTest::newRow("dds named png") << "dds"
                                   << "normal.png" << 16384;
}

void ImageClaimTest::lyingHeadersRefusedBeforeDecoding() {
    QFETCH(QString, kind);
    QFETCH(QString, name);
    QFETCH(int, maxSide);
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    // Sides whose float copy is over 1 GB (beyond the address space left below), and a few dozen
    // bytes of data: the claim alone must be refused.
    std::uniform_int_distribution<std::uint32_t> side(9000, static_cast<std::uint32_t>(maxSide));
    const std::uint32_t w = side(rng), h = side(rng);
    const std::size_t data = 16 + rng() % 64;
    const std::string file = m_dir->filePath(name).toStdString();
    QVERIFY(writeFileAtomically(file, lyingFile(kind.toStdString(), w, h, data, rng)).ok());
    ImageReadOptions options;
    options.maxSide = 1 << 30;
    Result<Image> image = Image{};
    {
        const AddressSpaceCap cap(512LL << 20);
        image = readImage(file, options);
    }
    QVERIFY2(!image.ok(), qPrintable(QString("seed %1: accepted").arg(seed)));
    const QString message = QString::fromStdString(image.error().message);
    QVERIFY2(message.startsWith(QString::fromStdString(file) + ": "), qPrintable(message));
    QVERIFY2(message.contains(QRegularExpression(
                 QString("claims %1x%2 texels, which a file of [0-9]+ bytes cannot hold")
                     .arg(w)
                     .arg(h))),
             qPrintable(QString("seed %1: %2").arg(seed).arg(message)));
}

namespace {

// A palette PNG as optimisers write them (level 9, no filter): `colours` entries, an index of
// `depth` bits, alpha for the first `alphas` entries, every texel index `pick(x, y)`.
bool writePalettePng(const std::string& path, int w, int h, int depth,
                     const std::vector<png_color>& colours, const std::vector<png_byte>& alphas,
                     const std::function<int(int, int)>& pick) {
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file)
        return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png)) != 0) {
        png_destroy_write_struct(&png, &info);
        std::fclose(file);
        return false;
    }
    png_init_io(png, file);
    png_set_compression_level(png, 9);
    png_set_filter(png, 0, PNG_FILTER_NONE);
    png_set_IHDR(png, info, w, h, depth, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_PLTE(png, info, colours.data(), static_cast<int>(colours.size()));
    if (!alphas.empty())
        png_set_tRNS(png, info, alphas.data(), static_cast<int>(alphas.size()), nullptr);
    png_write_info(png, info);
    std::vector<png_byte> row((static_cast<std::size_t>(w) * depth + 7) / 8);
    for (int y = 0; y < h; ++y) {
        std::fill(row.begin(), row.end(), 0);
        for (int x = 0; x < w; ++x) {
            const int bit = x * depth;
            row[bit / 8] |= static_cast<png_byte>(pick(x, y) << (8 - depth - bit % 8));
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return std::fclose(file) == 0;
}

} // namespace

// Flat roughness and AO maps as pngquant and oxipng write them: a few KB for 2048². Every texel is
// checked against its palette entry (and tRNS alpha).
void ImageClaimTest::palettePngsPass() {
    const unsigned seed = std::random_device{}();
    qInfo("seed %u", seed);
    std::mt19937 rng(seed);
    struct Case {
        int w, h, depth;
        bool trns, flat;
    };
    std::vector<Case> cases = {{2048, 2048, 8, false, true},
                               {1024, 1024, 1, false, true},
                               {2048, 2048, 4, true, true},
                               {4096, 1024, 2, true, true},
                               {2048, 2048, 8, true, false}};
    for (int i = 0; i < 12; ++i) { // seeded sizes and depths, flat or two-tone stripes
        const int depths[] = {1, 2, 4, 8};
        cases.push_back({1 + static_cast<int>(rng() % 3000), 1 + static_cast<int>(rng() % 3000),
                         depths[rng() % 4], rng() % 2 == 0, rng() % 3 != 0});
    }
    for (const Case& c : cases) {
        const int entries = 1 << c.depth;
        std::vector<png_color> colours(static_cast<std::size_t>(entries));
        for (png_color& p : colours)
            p = {static_cast<png_byte>(rng()), static_cast<png_byte>(rng()),
                 static_cast<png_byte>(rng())};
        std::vector<png_byte> alphas;
        if (c.trns)
            alphas.resize(static_cast<std::size_t>(entries));
        for (png_byte& a : alphas)
            a = static_cast<png_byte>(rng());
        const int a = c.flat && rng() % 2 == 0 ? 0 : static_cast<int>(rng() % entries);
        const int b = static_cast<int>(rng() % entries);
        const int stripe = 1 + static_cast<int>(rng() % 64);
        auto pick = [&](int x, int) { return c.flat || (x / stripe) % 2 == 0 ? a : b; };
        const std::string file = m_dir->filePath("palette.png").toStdString();
        QVERIFY(writePalettePng(file, c.w, c.h, c.depth, colours, alphas, pick));
        const QString what = QString("seed %1: %2x%3, %4-bit palette%5%6, %7 bytes")
                                 .arg(seed)
                                 .arg(c.w)
                                 .arg(c.h)
                                 .arg(c.depth)
                                 .arg(c.trns ? " with tRNS" : "")
                                 .arg(c.flat ? ", one colour" : ", stripes")
                                 .arg(QFileInfo(QString::fromStdString(file)).size());
        const Result<Image> image = readImage(file);
        QVERIFY2(image.ok(),
                 qPrintable(what + ": " +
                            QString::fromStdString(image.ok() ? "" : image.error().message)));
        QCOMPARE(image->channels, c.trns ? 4 : 3);
        for (int y = 0; y < c.h; ++y)
            for (int x = 0; x < c.w; ++x) {
                const int index = pick(x, y);
                const png_color& p = colours[static_cast<std::size_t>(index)];
                const float want[4] = {
                    p.red * (1.0f / 255.0f), p.green * (1.0f / 255.0f), p.blue * (1.0f / 255.0f),
                    c.trns ? alphas[static_cast<std::size_t>(index)] * (1.0f / 255.0f) : 1};
                for (int ch = 0; ch < image->channels; ++ch)
                    if (image->at(x, y, ch) != want[ch])
                        QFAIL(qPrintable(
                            what + QString(": texel (%1, %2) channel %3").arg(x).arg(y).arg(ch)));
            }
        qInfo("%s: read", qPrintable(what));
    }
}

// A real, well-formed 16384 x 8192 grey PNG of 130 KB: its float copy (1 GB) fits the file-size
// bound and the machine, but not the address space this process is allowed: refused by that
// limit, before decoding, not by a failed allocation.
void ImageClaimTest::memoryLimitOfTheProcess() {
    const int w = 16384, h = 8192;
    std::string idat;
    {
        z_stream z{};
        QCOMPARE(deflateInit(&z, 9), Z_OK);
        std::vector<unsigned char> row(w + 1, 0), out(1 << 16);
        for (int y = 0; y < h; ++y) {
            z.next_in = row.data();
            z.avail_in = static_cast<uInt>(row.size());
            const int flush = y + 1 == h ? Z_FINISH : Z_NO_FLUSH;
            do {
                z.next_out = out.data();
                z.avail_out = static_cast<uInt>(out.size());
                deflate(&z, flush);
                idat.append(reinterpret_cast<const char*>(out.data()), out.size() - z.avail_out);
            } while (z.avail_out == 0);
        }
        deflateEnd(&z);
    }
    auto chunk = [](const std::string& type, const std::string& data) {
        std::string c(4, '\0');
        putBig32(c, 0, static_cast<std::uint32_t>(data.size()));
        c += type + data + std::string(4, '\0');
        putBig32(c, c.size() - 4, crc32(c, 4, data.size() + 4));
        return c;
    };
    std::string ihdr(13, '\0');
    putBig32(ihdr, 0, w);
    putBig32(ihdr, 4, h);
    ihdr[8] = 8; // 8-bit grey, deflate, adaptive filters, not interlaced
    const std::string bytes = std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) +
                              chunk("IDAT", idat) + chunk("IEND", "");
    const std::string file = m_dir->filePath("big.png").toStdString();
    QVERIFY(writeFileAtomically(file, bytes).ok());
    Result<Image> image = Image{};
    {
        const AddressSpaceCap cap(512LL << 20);
        image = readImage(file);
    }
    QVERIFY(!image.ok());
    const QString message = QString::fromStdString(image.error().message);
    QVERIFY2(message.startsWith(QString::fromStdString(file) + ": the image is 16384x8192 texels "
                                                               "and needs 1.07 GB of memory"),
             qPrintable(message));
    QVERIFY2(message.contains(
                 QRegularExpression("more than the 0\\.[0-9]+ GB available to this process")),
             qPrintable(message));
}

QTEST_GUILESS_MAIN(ImageClaimTest)
#include "ImageClaimTest.moc"

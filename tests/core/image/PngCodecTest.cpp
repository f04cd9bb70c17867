// PNG is read and written by the core's own libpng codec, without loading the OpenImageIO module
// (core/src/image/PngCodec.h). It must give what OpenImageIO gave: every colour type and bit depth
// libpng writes, palettes, tRNS, interlacing and colour chunks, generated from seeds, read through
// readImage and through OpenImageIO directly, every value compared bit for bit; and every value
// written through writeImage quantised as OpenImageIO's writer does.

#include "parallax/image/ImageFile.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <cstring>
#include <fstream>
#include <png.h>
#include <random>
#include <zlib.h>

using namespace px;

namespace {

struct PngCase {
    int colour = PNG_COLOR_TYPE_GRAY;
    int depth = 8;
    bool trns = false;
    bool interlaced = false;
    int chunk = 0; // 0 none, 1 gAMA 1.0, 2 sRGB with gAMA and cHRM
    int width = 1, height = 1;
};

QString describe(const PngCase& c) {
    return QString("colour type %1, %2 bits%3%4, chunk %5, %6x%7")
        .arg(c.colour)
        .arg(c.depth)
        .arg(c.trns ? ", tRNS" : "")
        .arg(c.interlaced ? ", Adam7" : "")
        .arg(c.chunk)
        .arg(c.width)
        .arg(c.height);
}

int samplesOf(int colour) {
    switch (colour) {
    case PNG_COLOR_TYPE_GRAY_ALPHA:
        return 2;
    case PNG_COLOR_TYPE_RGB:
        return 3;
    case PNG_COLOR_TYPE_RGB_ALPHA:
        return 4;
    default:
        return 1; // grey, or a palette index
    }
}

// Writes the case with libpng itself, random content from `rng`. Empty string on success.
std::string writeCase(const std::string& path, const PngCase& c, std::mt19937& rng) {
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file)
        return "cannot create " + path;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png)) != 0) {
        png_destroy_write_struct(&png, &info);
        std::fclose(file);
        return "libpng failed writing " + path;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, c.width, c.height, c.depth, c.colour,
                 c.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    const int top = (1 << c.depth) - 1;
    std::uniform_int_distribution<int> value(0, top);
    std::vector<png_color> palette;
    std::vector<png_byte> alphas;
    if (c.colour == PNG_COLOR_TYPE_PALETTE) {
        palette.resize(static_cast<std::size_t>(top) + 1);
        for (png_color& p : palette)
            p = {static_cast<png_byte>(rng()), static_cast<png_byte>(rng()),
                 static_cast<png_byte>(rng())};
        png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
        if (c.trns) {
            alphas.resize(std::min<std::size_t>(palette.size(), 1 + rng() % palette.size()));
            for (png_byte& a : alphas)
                a = static_cast<png_byte>(rng());
            png_set_tRNS(png, info, alphas.data(), static_cast<int>(alphas.size()), nullptr);
        }
    } else if (c.trns) {
        png_color_16 key{};
        key.gray = static_cast<png_uint_16>(value(rng));
        key.red = static_cast<png_uint_16>(value(rng));
        key.green = static_cast<png_uint_16>(value(rng));
        key.blue = static_cast<png_uint_16>(value(rng));
        png_set_tRNS(png, info, nullptr, 0, &key);
    }
    if (c.chunk == 1)
        png_set_gAMA(png, info, 1.0);
    else if (c.chunk == 2)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    // Rows as packed samples, big-endian at 16 bits, written through libpng's packing.
    const int samples = c.width * samplesOf(c.colour);
    const std::size_t rowBytes = (static_cast<std::size_t>(samples) * c.depth + 7) / 8;
    std::vector<std::vector<png_byte>> rows(c.height, std::vector<png_byte>(rowBytes, 0));
    for (auto& row : rows) {
        for (int s = 0; s < samples; ++s) {
            // Extremes often: 0 and the largest value are where scaling goes wrong.
            int v = value(rng);
            if (rng() % 8 == 0)
                v = rng() % 2 == 0 ? 0 : top;
            if (c.depth == 16) {
                row[2 * s] = static_cast<png_byte>(v >> 8);
                row[2 * s + 1] = static_cast<png_byte>(v & 0xff);
            } else if (c.depth == 8) {
                row[s] = static_cast<png_byte>(v);
            } else {
                const int bit = s * c.depth;
                row[bit / 8] |= static_cast<png_byte>(v << (8 - c.depth - bit % 8));
            }
        }
    }
    std::vector<png_bytep> pointers;
    pointers.reserve(rows.size());
    for (auto& row : rows)
        pointers.push_back(row.data());
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return {};
}

// The file as OpenImageIO reads it, as the core did before it had its own PNG reader.
bool readWithOiio(const std::string& path, Image& out) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(path, &config);
    if (!input)
        return false;
    const OIIO::ImageSpec& spec = input->spec();
    out = Image(spec.width, spec.height, spec.nchannels);
    return input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out.pixels.data());
}

std::vector<PngCase> everyKind() {
    std::vector<PngCase> kinds;
    const std::vector<std::pair<int, std::vector<int>>> depths = {
        {PNG_COLOR_TYPE_GRAY, {1, 2, 4, 8, 16}},
        {PNG_COLOR_TYPE_GRAY_ALPHA, {8, 16}},
        {PNG_COLOR_TYPE_RGB, {8, 16}},
        {PNG_COLOR_TYPE_RGB_ALPHA, {8, 16}},
        {PNG_COLOR_TYPE_PALETTE, {1, 2, 4, 8}}};
    for (const auto& [colour, bits] : depths)
        for (int depth : bits)
            for (int trns = 0; trns < 2; ++trns) {
                if (trns != 0 && (colour & PNG_COLOR_MASK_ALPHA) != 0)
                    continue; // no tRNS beside an alpha channel
                for (int interlaced = 0; interlaced < 2; ++interlaced)
                    for (int chunk = 0; chunk < 3; ++chunk) {
                        PngCase c;
                        c.colour = colour;
                        c.depth = depth;
                        c.trns = trns != 0;
                        c.interlaced = interlaced != 0;
                        c.chunk = chunk;
                        kinds.push_back(c);
                    }
            }
    return kinds;
}

std::uint32_t bitsOf(float f) {
    std::uint32_t u = 0;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

} // namespace

class PngCodecTest : public QObject {
    Q_OBJECT
private slots:
    void readsEveryKindAsOpenImageIO();
    void writesEveryValueAsOpenImageIO_data();
    void writesEveryValueAsOpenImageIO();
    void damagedDataNamesTheFile();
    void neverLoadsTheImageModule();
    void parallelStripsAreOneStream_data();
    void parallelStripsAreOneStream();

private:
    QTemporaryDir m_dir;
    std::string path(const char* name) const { return m_dir.filePath(name).toStdString(); }
};

void PngCodecTest::readsEveryKindAsOpenImageIO() {
    const unsigned seed = std::random_device{}();
    qInfo("seed %u", seed);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> side(1, 37);
    // Every kind libpng writes: grey at 5 depths, palette at 4, the rest at 2, tRNS where the
    // type allows it, plain and Adam7, three colour chunks.
    QCOMPARE(everyKind().size(), std::size_t(156));
    int files = 0;
    for (int round = 0; round < 3; ++round) {
        for (PngCase c : everyKind()) {
            c.width = side(rng);
            c.height = side(rng);
            const std::string file = path("case.png");
            const std::string problem = writeCase(file, c, rng);
            QVERIFY2(problem.empty(), problem.c_str());
            Image expected;
            QVERIFY2(readWithOiio(file, expected), qPrintable(describe(c)));
            const Result<Image> read = readImage(file);
            QVERIFY2(read.ok(), read.ok() ? "" : read.error().message.c_str());
            const QString what = describe(c) + QString(", seed %1").arg(seed);
            QVERIFY2(read->width == expected.width && read->height == expected.height,
                     qPrintable(what));
            QVERIFY2(read->channels == expected.channels,
                     qPrintable(what + QString(": %1 channels, OpenImageIO %2")
                                           .arg(read->channels)
                                           .arg(expected.channels)));
            QVERIFY(!read->alphaOnly);
            for (std::size_t i = 0; i < expected.pixels.size(); ++i)
                if (bitsOf(read->pixels[i]) != bitsOf(expected.pixels[i]))
                    QFAIL(qPrintable(what + QString(": value %1 is %2, OpenImageIO %3")
                                                .arg(i)
                                                .arg(double(read->pixels[i]), 0, 'g', 9)
                                                .arg(double(expected.pixels[i]), 0, 'g', 9)));
            ++files;
        }
    }
    QCOMPARE(files, 3 * 156);
}

void PngCodecTest::writesEveryValueAsOpenImageIO_data() {
    QTest::addColumn<int>("bits");
    QTest::addColumn<int>("channels");
    QTest::addColumn<bool>("srgb");
    for (int bits : {8, 16})
        for (int channels = 1; channels <= 4; ++channels)
            for (bool srgb : {false, true})
                QTest::addRow("%d-bit %d channels%s", bits, channels, srgb ? " sRGB" : "")
                    << bits << channels << srgb;
}

void PngCodecTest::writesEveryValueAsOpenImageIO() {
    QFETCH(int, bits);
    QFETCH(int, channels);
    QFETCH(bool, srgb);
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    // Every half step between two codes (where rounding decides), the codes themselves, values
    // out of range, and random ones.
    const float top = bits == 8 ? 255.0f : 65535.0f;
    std::vector<float> values = {std::nanf(""), -1e30f,       -1.0f, -0.0f, 0.0f,
                                 1.0f,          1.0f + 1e-7f, 2.0f,  1e30f};
    const int steps = bits == 8 ? 256 : 4096;
    for (int k = 0; k < steps; ++k) {
        const float code =
            bits == 8 ? static_cast<float>(k) : static_cast<float>(k * 16 + rng() % 16);
        for (float offset : {0.0f, 0.5f, 0.49999997f, 0.50000006f})
            values.push_back((code + offset) / top);
    }
    std::uniform_real_distribution<float> any(-0.01f, 1.01f);
    while (values.size() % channels != 0 || values.size() < 20000)
        values.push_back(any(rng));
    const int width = 64;
    const int height = static_cast<int>((values.size() / channels + width - 1) / width);
    Image image(width, height, channels);
    std::copy(values.begin(), values.end(), image.pixels.data());

    ImageWriteOptions options;
    options.format = bits == 8 ? PixelFormat::UInt8 : PixelFormat::UInt16;
    options.srgb = srgb;
    const std::string ours = path("ours.png");
    QVERIFY(writeImage(ours, image, options).ok());
    const std::string theirs = path("theirs.png");
    auto output = OIIO::ImageOutput::create(theirs);
    OIIO::ImageSpec spec(width, height, channels,
                         bits == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
    spec.attribute("oiio:UnassociatedAlpha", 1); // as the core's writer always asked
    QVERIFY(output && output->open(theirs, spec));
    QVERIFY(output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) && output->close());

    Image a, b;
    QVERIFY(readWithOiio(ours, a));
    QVERIFY(readWithOiio(theirs, b));
    QCOMPARE(a.channels, channels);
    QCOMPARE(a.pixels.size(), b.pixels.size());
    int ties = 0; // made on purpose above: about a third of them
    for (std::size_t i = 0; i < values.size(); ++i) {
        // Round half up on the exact value (a float times 65535 is exact in double).
        const float v = values[i];
        const double exact = std::isnan(v) ? 0.0 : std::clamp(double(v), 0.0, 1.0) * top;
        const double expected = std::floor(exact + 0.5);
        const auto code = [&](const Image& img) {
            return std::lround(double(img.pixels[i]) * top);
        };
        if (double(code(a)) != expected)
            QFAIL(qPrintable(QString("seed %1: %2 written as %3, not %4")
                                 .arg(seed)
                                 .arg(double(v), 0, 'g', 9)
                                 .arg(code(a))
                                 .arg(expected)));
        // OpenImageIO agrees but within a float's precision of a half, where its own writer
        // rounds one way in some positions of a row and the other way in others.
        const double ulp = double(std::nextafter(std::abs(v), 2.0f) - std::abs(v)) * top;
        const bool tie = std::abs(exact - std::floor(exact) - 0.5) <= 2.0 * ulp;
        ties += tie && code(a) != code(b) ? 1 : 0;
        if (code(a) != code(b) && !tie)
            QFAIL(qPrintable(QString("seed %1: %2 written as %3, by OpenImageIO as %4")
                                 .arg(seed)
                                 .arg(double(v), 0, 'g', 9)
                                 .arg(code(a))
                                 .arg(code(b))));
    }
    qInfo("%d of the values next to a half round otherwise in OpenImageIO", ties);
    // sRGB says so in the file (with the gAMA and cHRM libpng writes beside it); linear says
    // nothing (ExportPng checks what engines make of both).
    std::ifstream in(ours, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* chunk : {"sRGB", "gAMA", "cHRM"})
        QCOMPARE(bytes.find(chunk) != std::string::npos, srgb);
}

void PngCodecTest::damagedDataNamesTheFile() {
    // A valid structure (every chunk's CRC right) around data that does not inflate.
    Image image(40, 30, 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = static_cast<float>(i % 97) / 96.0f;
    const std::string file = path("damaged.png");
    QVERIFY(writeImage(file, image, {}).ok());
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const std::size_t idat = bytes.find("IDAT");
    QVERIFY(idat != std::string::npos);
    const std::uint32_t length = static_cast<unsigned char>(bytes[idat - 4]) << 24 |
                                 static_cast<unsigned char>(bytes[idat - 3]) << 16 |
                                 static_cast<unsigned char>(bytes[idat - 2]) << 8 |
                                 static_cast<unsigned char>(bytes[idat - 1]);
    for (std::uint32_t k = 8; k < length; ++k)
        bytes[idat + 4 + k] = static_cast<char>(0xff - k);
    const std::uint32_t crc = static_cast<std::uint32_t>(
        ::crc32(0, reinterpret_cast<const unsigned char*>(bytes.data() + idat), length + 4));
    for (int k = 0; k < 4; ++k)
        bytes[idat + 4 + length + k] = static_cast<char>(crc >> (24 - 8 * k));
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    const Result<Image> read = readImage(file);
    QVERIFY(!read.ok());
    QVERIFY2(read.error().message.rfind(file + ": the file is damaged (its image data does not "
                                               "decode: ",
                                        0) == 0,
             read.error().message.c_str());
}

void PngCodecTest::neverLoadsTheImageModule() {
    // Everything above read and wrote only PNG: the OpenImageIO module was never mapped (this
    // test links OpenImageIO itself, as the reference, so that library is here anyway).
    std::ifstream maps("/proc/self/maps");
    const std::string mapped((std::istreambuf_iterator<char>(maps)),
                             std::istreambuf_iterator<char>());
    QVERIFY2(mapped.find("libparallax-oiio") == std::string::npos,
             "reading or writing a PNG loaded the OpenImageIO module");
}

void PngCodecTest::parallelStripsAreOneStream_data() {
    QTest::addColumn<int>("bits");
    QTest::addColumn<int>("channels");
    for (int bits : {8, 16})
        for (int channels = 1; channels <= 4; ++channels)
            QTest::addRow("%d-bit %d channels", bits, channels) << bits << channels;
}

// Images of many strips (PngDeflate.h): the IDAT data is one zlib stream that zlib itself inflates
// with its Adler-32 checked, to one filter byte and row a line; OpenImageIO decodes every value
// as quantised; and the strips cost no more than 1% against libpng's one stream at that level.
void PngCodecTest::parallelStripsAreOneStream() {
    QFETCH(int, bits);
    QFETCH(int, channels);
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    const int width = 200 + static_cast<int>(rng() % 1300),
              height = 300 + static_cast<int>(rng() % 1200);
    const double top = bits == 8 ? 255.0 : 65535.0;
    Image image(width, height, channels);
    // Rows of noise, flat runs and ramps: every filter gets chosen somewhere.
    for (int y = 0; y < height; ++y) {
        const int kind = static_cast<int>(rng() % 3);
        const float level = static_cast<float>(rng() % 1000) / 999.0f;
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                image.at(x, y, c) = kind == 0   ? static_cast<float>(rng() % 100000) / 99999.0f
                                    : kind == 1 ? level
                                                : static_cast<float>(x + c * 7) / width;
    }
    const std::string ours = path("strips.png");
    ImageWriteOptions options;
    options.format = bits == 8 ? PixelFormat::UInt8 : PixelFormat::UInt16;
    QVERIFY(writeImage(ours, image, options).ok());
    std::ifstream in(ours, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

    std::string stream; // every IDAT's data in order
    for (std::size_t at = 8; at + 12 <= bytes.size();) {
        const std::uint32_t length = static_cast<unsigned char>(bytes[at]) << 24 |
                                     static_cast<unsigned char>(bytes[at + 1]) << 16 |
                                     static_cast<unsigned char>(bytes[at + 2]) << 8 |
                                     static_cast<unsigned char>(bytes[at + 3]);
        if (bytes.compare(at + 4, 4, "IDAT") == 0)
            stream += bytes.substr(at + 8, length);
        at += 12 + length;
    }
    const std::size_t lineBytes = static_cast<std::size_t>(width) * channels * bits / 8 + 1;
    std::vector<unsigned char> filtered(lineBytes * height + 1);
    uLongf size = static_cast<uLongf>(filtered.size());
    QCOMPARE(::uncompress(filtered.data(), &size, reinterpret_cast<const Bytef*>(stream.data()),
                          static_cast<uLong>(stream.size())),
             Z_OK);
    QCOMPARE(static_cast<std::size_t>(size), lineBytes * height);

    Image back;
    QVERIFY(readWithOiio(ours, back));
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const double want = std::floor(std::clamp(double(image.pixels[i]), 0.0, 1.0) * top + 0.5);
        if (double(std::lround(double(back.pixels[i]) * top)) != want)
            QFAIL(qPrintable(
                QString("seed %1: %2x%3, value %4").arg(seed).arg(width).arg(height).arg(i)));
    }

    // libpng's own file of the same values, its filter heuristic, the level the core uses (5).
    const std::string theirs = path("serial.png");
    FILE* file = std::fopen(theirs.c_str(), "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    QVERIFY(file && png && info);
    if (setjmp(png_jmpbuf(png)) != 0)
        QFAIL("libpng failed writing the reference");
    png_init_io(png, file);
    png_set_compression_level(png, 5);
    static constexpr int kColour[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                      PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    png_set_IHDR(png, info, width, height, bits, kColour[channels - 1], PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<png_byte> row(lineBytes - 1);
    for (int y = 0; y < height; ++y) {
        for (int i = 0; i < width * channels; ++i) {
            const auto v = static_cast<unsigned>(std::floor(
                std::clamp(double(image.pixels[static_cast<std::size_t>(y) * width * channels + i]),
                           0.0, 1.0) *
                    top +
                0.5));
            if (bits == 16) {
                row[2 * i] = static_cast<png_byte>(v >> 8);
                row[2 * i + 1] = static_cast<png_byte>(v & 0xff);
            } else {
                row[i] = static_cast<png_byte>(v);
            }
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    const auto serial = QFileInfo(QString::fromStdString(theirs)).size();
    qInfo("seed %u: %dx%d: %zu bytes in parallel strips, %lld by libpng alone", seed, width, height,
          bytes.size(), static_cast<long long>(serial));
    QVERIFY2(static_cast<double>(bytes.size()) <= 1.01 * static_cast<double>(serial) + 1024,
             qPrintable(QString("seed %1").arg(seed)));
}

QTEST_GUILESS_MAIN(PngCodecTest)
#include "PngCodecTest.moc"

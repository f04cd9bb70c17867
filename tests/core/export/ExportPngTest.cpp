// Every PNG an export writes reads the same through libpng's gamma-aware decoding (as Godot's and
// Unity's loaders do) as through OpenImageIO: linear maps carry no gAMA, sRGB, iCCP or cHRM
// chunk (a gAMA 1.0 would turn a flat normal's 0.498 into 0.729 in Godot); only albedo may say
// sRGB (with its gAMA and cHRM).

#include "parallax/export/Exporter.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <cstring>
#include <png.h>

using namespace px;
namespace fs = std::filesystem;

namespace {

// The chunk types of a PNG file, in order.
QStringList chunksOf(const std::string& bytes) {
    QStringList chunks;
    for (std::size_t at = 8; at + 8 <= bytes.size();) {
        const std::uint32_t length = static_cast<unsigned char>(bytes[at]) << 24 |
                                     static_cast<unsigned char>(bytes[at + 1]) << 16 |
                                     static_cast<unsigned char>(bytes[at + 2]) << 8 |
                                     static_cast<unsigned char>(bytes[at + 3]);
        chunks << QString::fromStdString(bytes.substr(at + 4, 4));
        at += 12 + length;
    }
    return chunks;
}

// Decodes as a gamma-aware loader does: libpng told the display is sRGB (png_set_gamma), which
// converts the values of a file whose gAMA, sRGB or iCCP chunk says otherwise and leaves a file
// without one as stored. Values in [0, 1]; empty with `problem` set on a libpng error.
struct PngReader {
    const std::string* bytes;
    std::size_t at;
};

void readFromMemory(png_structp png, png_bytep out, png_size_t count) {
    auto* reader = static_cast<PngReader*>(png_get_io_ptr(png));
    if (reader->at + count > reader->bytes->size())
        png_error(png, "read past the end of the file");
    std::memcpy(out, reader->bytes->data() + reader->at, count);
    reader->at += count;
}

std::vector<float> decodeLikeAnEngine(const std::string& bytes, int& channels, QString& problem) {
    // Everything with a destructor lives before setjmp: a longjmp must not skip one.
    std::vector<float> values;
    std::vector<png_byte> data;
    std::vector<png_bytep> rows;
    PngReader reader{&bytes, 0};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        problem = "libpng could not read the file";
        png_destroy_read_struct(&png, &info, nullptr);
        return {};
    }
    png_set_read_fn(png, &reader, readFromMemory);
    png_read_info(png, info);
    png_set_gamma(png, PNG_DEFAULT_sRGB, PNG_DEFAULT_sRGB);
    if (png_get_bit_depth(png, info) == 16)
        png_set_swap(png); // host order
    png_read_update_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info);
    const png_uint_32 height = png_get_image_height(png, info);
    const bool sixteen = png_get_bit_depth(png, info) == 16;
    channels = png_get_channels(png, info);
    const std::size_t rowBytes = png_get_rowbytes(png, info);
    data.resize(rowBytes * height);
    rows.resize(height);
    for (png_uint_32 y = 0; y < height; ++y)
        rows[y] = data.data() + y * rowBytes;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    const std::size_t count = static_cast<std::size_t>(width) * height * channels;
    values.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (sixteen) {
            std::uint16_t v = 0;
            std::memcpy(&v, data.data() + 2 * i, 2);
            values[i] = v / 65535.0f;
        } else {
            values[i] = data[i] / 255.0f;
        }
    }
    return values;
}

Image constant(int w, int h, std::initializer_list<float> values) {
    Image image(w, h, static_cast<int>(values.size()));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int c = 0;
            for (float v : values)
                image.at(x, y, c++) = v;
        }
    }
    return image;
}

} // namespace

class ExportPngTest : public QObject {
    Q_OBJECT

private slots:
    void linearMapsDecodeTheSameInEngines_data();
    void linearMapsDecodeTheSameInEngines();
};

void ExportPngTest::linearMapsDecodeTheSameInEngines_data() {
    QTest::addColumn<int>("format");
    QTest::addColumn<int>("technique");
    for (ExportFormat f : {ExportFormat::Package, ExportFormat::Gltf, ExportFormat::Godot,
                           ExportFormat::Unreal, ExportFormat::Unity}) {
        for (Technique t : {Technique::Pom, Technique::Cone, Technique::Pyramid}) {
            QTest::newRow((std::string(toString(f)) + " " + std::string(info(t).name)).c_str())
                << static_cast<int>(f) << static_cast<int>(t);
        }
    }
}

void ExportPngTest::linearMapsDecodeTheSameInEngines() {
    QFETCH(int, format);
    QFETCH(int, technique);
    QTemporaryDir dir;
    const fs::path root(dir.path().toStdString());
    auto write = [&](const std::string& name, const Image& image, PixelFormat f, bool srgb) {
        ImageWriteOptions o;
        o.format = f;
        o.srgb = srgb;
        QVERIFY(writeImage((root / name).string(), image, o).ok());
    };
    write("m_height.png", makeProceduralMap(ProceduralMap::Bricks, 32, 16).toImage(),
          PixelFormat::UInt16, false);
    write("m_albedo.png", constant(32, 16, {0.8f, 0.4f, 0.2f}), PixelFormat::UInt8, true);
    write("m_normal.png", constant(32, 16, {0.498f, 0.498f, 1.0f}), PixelFormat::UInt8, false);
    write("m_roughness.png", constant(32, 16, {0.118f}), PixelFormat::UInt8, false);
    write("m_ao.png", constant(32, 16, {0.6f}), PixelFormat::UInt8, false);
    write("m_metallic.png", constant(32, 16, {0.25f}), PixelFormat::UInt8, false);
    Material material;
    material.name = "m";
    material.maps = {"m_albedo.png", "m_height.png",    "m_normal.png",  "", "",
                     "m_ao.png",     "m_roughness.png", "m_metallic.png"};
    material.technique = static_cast<Technique>(technique);
    material.params = info(material.technique).defaults;
    ExportOptions options;
    options.format = static_cast<ExportFormat>(format);
    options.outDir = (root / "out").string();
    Result<ExportResult> result = exportMaterial(material, (root / "m.json").string(), options);
    QVERIFY2(result.ok(), result.ok() ? "" : result.error().message.c_str());

    int checked = 0;
    for (const std::string& name : result->files) {
        if (fs::path(name).extension() != ".png")
            continue;
        const std::string file = (root / "out" / name).string();
        const std::string bytes = *readTextFile(file);
        const QStringList chunks = chunksOf(bytes);
        const bool albedo = QString::fromStdString(name).contains(QRegularExpression(
            "albedo|basecolor|_BC\\.png$", QRegularExpression::CaseInsensitiveOption));
        for (const char* colour : {"gAMA", "iCCP", "cHRM", "sRGB"}) {
            // Albedo may say sRGB, with the gAMA and cHRM that go with it (libpng writes the
            // three together; loaders that know sRGB use that chunk).
            if (albedo && QString(colour) != "iCCP")
                continue;
            QVERIFY2(!chunks.contains(colour), qPrintable(QString::fromStdString(name) + ": " +
                                                          colour + " in " + chunks.join(' ')));
        }
        int channels = 0;
        QString problem;
        const std::vector<float> engine = decodeLikeAnEngine(bytes, channels, problem);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const Result<Image> oiio = readImage(file);
        QVERIFY(oiio.ok());
        QCOMPARE(channels, oiio->channels);
        QCOMPARE(engine.size(), oiio->pixels.size());
        for (std::size_t i = 0; i < engine.size(); ++i) {
            if (std::abs(engine[i] - oiio->pixels[i]) > 0.5f / 255.0f)
                QFAIL(qPrintable(QString("%1: value %2 reads %3 in libpng, %4 in OIIO")
                                     .arg(QString::fromStdString(name))
                                     .arg(i)
                                     .arg(engine[i])
                                     .arg(oiio->pixels[i])));
        }
        ++checked;
    }
    QVERIFY(checked >= 2); // at least the height and one other map
}

QTEST_GUILESS_MAIN(ExportPngTest)
#include "ExportPngTest.moc"

// Files holding several images are never read by their first one silently: a multi-page TIFF, a
// multi-part EXR and a layered EXR (albedo.R, height.Y ...) are refused with the list of what they
// hold unless ImageReadOptions names one (page, or layer: an EXR part or channel layer), and the
// one named is read texel for texel; a choice the file does not have is refused with the list.

#include "parallax/image/ImageFile.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QtTest>
#include <random>

using namespace px;

namespace {

std::vector<std::string> g_notes;
void keepNote(const std::string& note) {
    g_notes.push_back(note);
}

std::vector<float> noise(std::size_t count, std::mt19937& rng) {
    std::vector<float> v(count);
    for (float& t : v)
        t = static_cast<float>(rng() % 65536) * (1.0f / 65535.0f); // a 16-bit code, as read back
    return v;
}

QString messageOf(const Result<Image>& image) {
    return image.ok() ? QString("(read)") : QString::fromStdString(image.error().message);
}

} // namespace

class ImageChoiceTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setImageNoteSink(keepNote); }
    void multiPageTiff();
    void multiPartExr();
    void layeredExr();
    void singleImagesTakeNoChoice();

private:
    QTemporaryDir m_dir;
};

void ImageChoiceTest::multiPageTiff() {
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    const std::string file = m_dir.filePath("pages.tif").toStdString();
    std::vector<OIIO::ImageSpec> specs;
    std::vector<std::vector<float>> pages;
    const int count = 2 + static_cast<int>(rng() % 3);
    for (int p = 0; p < count; ++p) {
        specs.emplace_back(5 + static_cast<int>(rng() % 60), 5 + static_cast<int>(rng() % 60), 1,
                           OIIO::TypeDesc::UINT16);
        pages.push_back(
            noise(static_cast<std::size_t>(specs.back().width) * specs.back().height, rng));
    }
    auto out = OIIO::ImageOutput::create(file);
    QVERIFY(out && out->supports("multiimage"));
    QVERIFY(out->open(file, count, specs.data()));
    for (int p = 0; p < count; ++p) {
        if (p > 0)
            QVERIFY(out->open(file, specs[p], OIIO::ImageOutput::AppendSubimage));
        QVERIFY(out->write_image(OIIO::TypeDesc::FLOAT, pages[p].data()));
    }
    QVERIFY(out->close());

    const Result<Image> unchosen = readImage(file);
    const QString said = messageOf(unchosen);
    QVERIFY2(!unchosen.ok(), qPrintable(said));
    QVERIFY2(said.startsWith(QString::fromStdString(file) + ": the file holds " +
                             QString::number(count) + " pages: "),
             qPrintable(said));
    for (int p = 0; p < count; ++p)
        QVERIFY2(
            said.contains(
                QString("%1 (%2x%3, 1 channel)").arg(p).arg(specs[p].width).arg(specs[p].height)),
            qPrintable(said));
    QVERIFY2(said.contains("--page"), qPrintable(said));

    for (int p = 0; p < count; ++p) {
        ImageReadOptions options;
        options.page = p;
        g_notes.clear();
        const Result<Image> page = readImage(file, options);
        QVERIFY2(page.ok(), qPrintable(messageOf(page)));
        QCOMPARE(page->width, specs[p].width);
        QCOMPARE(page->height, specs[p].height);
        for (std::size_t i = 0; i < pages[p].size(); ++i)
            if (page->pixels[i] != pages[p][i])
                QFAIL(qPrintable(QString("seed %1: page %2 value %3").arg(seed).arg(p).arg(i)));
        QCOMPARE(g_notes.size(), std::size_t(1));
        QVERIFY2(g_notes[0] == file + ": read page " + std::to_string(p), g_notes[0].c_str());
    }
    ImageReadOptions beyond;
    beyond.page = count;
    const Result<Image> missing = readImage(file, beyond);
    QVERIFY2(!missing.ok() &&
                 messageOf(missing).contains(QString("has no page %1; it holds").arg(count)),
             qPrintable(messageOf(missing)));
}

void ImageChoiceTest::multiPartExr() {
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    const std::string file = m_dir.filePath("parts.exr").toStdString();
    OIIO::ImageSpec specs[2] = {OIIO::ImageSpec(17, 9, 3, OIIO::TypeDesc::FLOAT),
                                OIIO::ImageSpec(23, 11, 1, OIIO::TypeDesc::FLOAT)};
    for (OIIO::ImageSpec& spec : specs) { // OpenEXR's parts share one display window
        spec.full_width = 23;
        spec.full_height = 11;
    }
    specs[0].attribute("name", "albedo");
    specs[1].attribute("name", "height");
    const std::vector<float> albedo = noise(17 * 9 * 3, rng), height = noise(23 * 11, rng);
    auto out = OIIO::ImageOutput::create(file);
    QVERIFY(out && out->open(file, 2, specs));
    QVERIFY(out->write_image(OIIO::TypeDesc::FLOAT, albedo.data()));
    QVERIFY(out->open(file, specs[1], OIIO::ImageOutput::AppendSubimage));
    QVERIFY(out->write_image(OIIO::TypeDesc::FLOAT, height.data()));
    QVERIFY(out->close());

    const Result<Image> unchosen = readImage(file);
    const QString said = messageOf(unchosen);
    QVERIFY2(said.startsWith(
                 QString::fromStdString(file) +
                 ": the file holds 2 parts: albedo (17x9, 3 channels), height (23x11, 1 channel)"),
             qPrintable(said));
    ImageReadOptions byName;
    byName.layer = "height";
    const Result<Image> h = readImage(file, byName);
    QVERIFY2(h.ok(), qPrintable(messageOf(h)));
    QCOMPARE(h->width, 23);
    QCOMPARE(h->channels, 1);
    for (std::size_t i = 0; i < height.size(); ++i)
        QCOMPARE(h->pixels[i], height[i]);
    ImageReadOptions byNumber;
    byNumber.page = 0;
    const Result<Image> a = readImage(file, byNumber);
    QVERIFY2(a.ok(), qPrintable(messageOf(a)));
    QCOMPARE(a->channels, 3);
    for (std::size_t i = 0; i < albedo.size(); ++i)
        QCOMPARE(a->pixels[i], albedo[i]);
    ImageReadOptions wrong;
    wrong.layer = "roughness";
    const QString refused = messageOf(readImage(file, wrong));
    QVERIFY2(refused.contains("the file holds 2 parts: albedo"), qPrintable(refused));
}

void ImageChoiceTest::layeredExr() {
    const unsigned seed = std::random_device{}();
    std::mt19937 rng(seed);
    const std::string file = m_dir.filePath("layers.exr").toStdString();
    const int w = 3 + static_cast<int>(rng() % 40), h = 3 + static_cast<int>(rng() % 40);
    OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"albedo.R", "albedo.G", "albedo.B", "height.Y"};
    spec.alpha_channel = -1;
    const std::vector<float> texels = noise(static_cast<std::size_t>(w) * h * 4, rng);
    auto out = OIIO::ImageOutput::create(file);
    QVERIFY(out && out->open(file, spec) &&
            out->write_image(OIIO::TypeDesc::FLOAT, texels.data()) && out->close());

    const QString said = messageOf(readImage(file));
    QVERIFY2(said.startsWith(QString::fromStdString(file) + ": the file holds 2 layers: "),
             qPrintable(said));
    QVERIFY2(said.contains("height: height.Y") && said.contains("albedo: albedo."),
             qPrintable(said));
    ImageReadOptions options;
    options.layer = "height";
    const Result<Image> height = readImage(file, options);
    QVERIFY2(height.ok(), qPrintable(messageOf(height)));
    QCOMPARE(height->channels, 1);
    for (int i = 0; i < w * h; ++i)
        QCOMPARE(height->pixels[i], texels[static_cast<std::size_t>(i) * 4 + 3]);
    options.layer = "albedo";
    const Result<Image> albedo = readImage(file, options);
    QVERIFY2(albedo.ok(), qPrintable(messageOf(albedo)));
    QCOMPARE(albedo->channels, 3);
    for (int i = 0; i < w * h; ++i)
        for (int c = 0; c < 3; ++c)
            QCOMPARE(albedo->pixels[static_cast<std::size_t>(i) * 3 + c],
                     texels[static_cast<std::size_t>(i) * 4 + c]);
    options.layer = "normal";
    const QString refused = messageOf(readImage(file, options));
    QVERIFY2(refused.contains("has no layer 'normal'; its layers: "), qPrintable(refused));
}

void ImageChoiceTest::singleImagesTakeNoChoice() {
    const std::string file = m_dir.filePath("one.png").toStdString();
    QVERIFY(writeImage(file, Image(4, 4, 1), {}).ok());
    ImageReadOptions page;
    page.page = 2;
    QVERIFY(messageOf(readImage(file, page)).contains("one image, with no pages or layers"));
    page.page = 0;
    QVERIFY(readImage(file, page).ok());
}

QTEST_GUILESS_MAIN(ImageChoiceTest)
#include "ImageChoiceTest.moc"

// Conformance on third-party data nobody here tuned for (PX_SHARED_DIR/testdata, never shipped):
// LearnOpenGL's bricks2 and toy_box (depth maps; green towards increasing rows, DirectX Y- here;
// see their README) and graphics-snippets' example_1 (a height map, white = high). The real files
// are imported as they ship and copied under the names and packings texture libraries and games
// use (Poly Haven, ambientCG, Doom 3, tags glued to the name, Tesseract's height or depth in the
// normal map's alpha): each must read the right file per map, depth or height and the green from
// the data, and hold the file's relief texel for texel. A normal map alone must give back a
// height that follows the real depth map.

#include "ConventionSets.h"
#include "TestSupport.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/TextureSetImport.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <filesystem>

using namespace px;

namespace {

namespace fs = std::filesystem;

std::string learn(const std::string& file) {
    return test::sharedTestData("learnopengl/" + file);
}

Image readOrDie(const std::string& path) {
    Result<Image> image = readImage(path);
    if (!image)
        qFatal("%s", image.error().message.c_str());
    return std::move(*image);
}

// The height the material should hold: channel 0 of the file, inverted for a depth map.
HeightField relief(const std::string& path, bool depth) {
    const Image image = readOrDie(path);
    HeightField out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            out.at(x, y) = depth ? 1.0f - image.at(x, y) : image.at(x, y);
    return out;
}

// The normal map's RGB with `alpha` in its fourth channel, written as PNG (8 bits, exact).
void packAlpha(const std::string& normal, const HeightField& alpha, const std::string& out) {
    if (!writeImage(out, test::withAlpha(readOrDie(normal), alpha), {}))
        qFatal("cannot write %s", out.c_str());
}

float worstDifference(const HeightField& a, const HeightField& b) {
    if (a.width != b.width || a.height != b.height)
        return 1.0f;
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.texels.size(); ++i)
        worst = std::max(worst, std::abs(a.texels[i] - b.texels[i]));
    return worst;
}

double correlation(const HeightField& a, const HeightField& b) {
    const double n = static_cast<double>(a.texels.size());
    double ma = 0.0, mb = 0.0;
    for (std::size_t i = 0; i < a.texels.size(); ++i) {
        ma += a.texels[i];
        mb += b.texels[i];
    }
    ma /= n;
    mb /= n;
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (std::size_t i = 0; i < a.texels.size(); ++i) {
        const double da = a.texels[i] - ma, db = b.texels[i] - mb;
        ab += da * db;
        aa += da * da;
        bb += db * db;
    }
    return ab / std::sqrt(aa * bb);
}

std::string reportOf(const ImportedSet& set) {
    std::string text;
    for (const std::string& line : importSummary(set))
        text += line + "\n";
    return text;
}

Result<ImportedSet> importFolder(const std::string& folder, const std::string& set = {}) {
    Result<std::vector<std::string>> files = folderFiles(folder);
    if (!files)
        return files.error();
    Result<TextureSetPlan> plan = planTextureSet(*files, folder, set);
    if (!plan)
        return plan.error();
    return importTextureSet(*plan);
}

bool endsWith(const std::string& path, const std::string& name) {
    return name.empty() ? path.empty() : path.ends_with("/" + name);
}

} // namespace

class TextureSetConformanceTest : public QObject {
    Q_OBJECT
private slots:
    void learnOpenGlAsShipped_data() {
        QTest::addColumn<QString>("set");
        QTest::addColumn<QString>("albedo");
        QTest::addColumn<QString>("height");
        QTest::newRow("bricks2") << "bricks2"
                                 << "bricks2.jpg"
                                 << "bricks2_disp.jpg";
        QTest::newRow("toy_box") << "toy_box"
                                 << "toy_box_diffuse.png"
                                 << "toy_box_disp.png";
    }
    void learnOpenGlAsShipped() {
        QFETCH(QString, set);
        QFETCH(QString, albedo);
        QFETCH(QString, height);
        const Result<ImportedSet> imported =
            importFolder(test::sharedTestData("learnopengl"), set.toStdString());
        QVERIFY2(imported, imported ? "" : imported.error().message.c_str());
        const std::string report = reportOf(*imported);
        const Material& m = imported->material;
        QVERIFY2(endsWith(m.maps.albedo, albedo.toStdString()), report.c_str());
        QVERIFY2(endsWith(m.maps.height, height.toStdString()), report.c_str());
        QVERIFY2(m.heightIsDepth && imported->relief.fromData, report.c_str());
        QVERIFY2(m.normalGreen == NormalGreen::DirectX, report.c_str());
        QVERIFY2(worstDifference(imported->assets.height, relief(m.maps.height, true)) < 1e-6f,
                 report.c_str());
        QVERIFY2(report.find("Ignored: wood.png") != std::string::npos, report.c_str());
    }

    // The real files under other names and packings; green and depth are never in the names
    // below except where the name is right (NormalDX, nor_dx).
    void renamedAsLibrariesAndGamesNameThem_data() {
        QTest::addColumn<QStringList>("copies"); // source=target pairs; "+alpha" packs
        QTest::addColumn<QString>("height");
        QTest::addColumn<bool>("alpha");
        QTest::addColumn<bool>("depth");
        QTest::addColumn<QString>("normal");
        QTest::addColumn<QString>("albedo");
        QTest::newRow("poly-haven")
            << QStringList{"bricks2.jpg=brick_wall_diff_1k.jpg",
                           "bricks2_normal.jpg=brick_wall_nor_dx_1k.jpg",
                           "bricks2_disp.jpg=brick_wall_disp_1k.jpg"}
            << "brick_wall_disp_1k.jpg" << false << true << "brick_wall_nor_dx_1k.jpg"
            << "brick_wall_diff_1k.jpg";
        QTest::newRow("ambientcg")
            << QStringList{"toy_box_diffuse.png=ToyBox001_1K-PNG_Color.png",
                           "toy_box_normal.png=ToyBox001_1K-PNG_NormalDX.png",
                           "toy_box_disp.png=ToyBox001_1K-PNG_Displacement.png"}
            << "ToyBox001_1K-PNG_Displacement.png" << false << true
            << "ToyBox001_1K-PNG_NormalDX.png"
            << "ToyBox001_1K-PNG_Color.png";
        QTest::newRow("glued-tags")
            << QStringList{"bricks2.jpg=wall01.jpg", "bricks2_normal.jpg=wall01n.jpg",
                           "bricks2_disp.jpg=wall01z.jpg"}
            << "wall01z.jpg" << false << true << "wall01n.jpg"
            << "wall01.jpg";
        QTest::newRow("doom3") << QStringList{"toy_box_diffuse.png=crate_d.png",
                                              "toy_box_normal.png=crate_local.png",
                                              "toy_box_disp.png=crate_h.png"}
                               << "crate_h.png" << false << true << "crate_local.png"
                               << "crate_d.png";
        QTest::newRow("tesseract-height-in-alpha")
            << QStringList{"toy_box_diffuse.png=box.png", "toy_box_normal.png=box_nm.png+height"}
            << "box_nm.png" << true << false << "box_nm.png"
            << "box.png";
        QTest::newRow("depth-in-alpha-variant-letter")
            << QStringList{"bricks2.jpg=wall1a.jpg", "bricks2_normal.jpg=wall1_n.png+depth"}
            << "wall1_n.png" << true << true << "wall1_n.png"
            << "wall1a.jpg";
    }
    void renamedAsLibrariesAndGamesNameThem() {
        QFETCH(QStringList, copies);
        QFETCH(QString, height);
        QFETCH(bool, alpha);
        QFETCH(bool, depth);
        QFETCH(QString, normal);
        QFETCH(QString, albedo);
        QTemporaryDir dir;
        const std::string root = dir.path().toStdString();
        HeightField truth;
        for (const QString& copy : copies) {
            const QStringList parts = copy.split('=');
            const std::string source = learn(parts[0].toStdString());
            std::string target = parts[1].toStdString();
            if (const std::size_t plus = target.find('+'); plus != std::string::npos) {
                // The set's depth map, as height or as depth, in the normal map's alpha.
                const std::string disp = source.substr(0, source.rfind("_normal")) +
                                         (source.ends_with(".jpg") ? "_disp.jpg" : "_disp.png");
                const bool packDepth = target.substr(plus + 1) == "depth";
                truth = relief(disp, true);
                packAlpha(source, packDepth ? relief(disp, false) : truth,
                          root + "/" + target.substr(0, plus));
                target.resize(plus);
            } else {
                QVERIFY(fs::copy_file(source, root + "/" + target));
                if (target == height.toStdString())
                    truth = relief(source, true);
            }
        }
        const Result<ImportedSet> imported = importFolder(root);
        QVERIFY2(imported, imported ? "" : imported.error().message.c_str());
        const std::string report = reportOf(*imported);
        const Material& m = imported->material;
        QVERIFY2(endsWith(m.maps.height, height.toStdString()), report.c_str());
        QVERIFY2(endsWith(m.maps.normal, normal.toStdString()), report.c_str());
        QVERIFY2(endsWith(m.maps.albedo, albedo.toStdString()), report.c_str());
        QVERIFY2((m.heightChannel == HeightChannel::Alpha) == alpha, report.c_str());
        QVERIFY2(m.heightIsDepth == depth, report.c_str());
        QVERIFY2(m.normalGreen == NormalGreen::DirectX, report.c_str());
        const float worst = worstDifference(imported->assets.height, truth);
        QVERIFY2(worst < 1e-6f, qPrintable(QString("height off by %1\n").arg(worst) +
                                           QString::fromStdString(report)));
    }

    // Only the real normal map: the height integrated from it follows the real depth map.
    void normalOnlyGivesBackTheRelief_data() {
        QTest::addColumn<QString>("normal");
        QTest::addColumn<QString>("disp");
        QTest::addColumn<double>("least");
        // Measured r = 0.999 (bricks2) and 0.603 (toy_box). The toy box's panels are flat levels
        // with steps its normal map does not hold (and its normals are 0.58 long), so only the
        // layout of its relief can come back, not the levels across the steps.
        QTest::newRow("bricks2") << "bricks2_normal.jpg"
                                 << "bricks2_disp.jpg" << 0.95;
        QTest::newRow("toy_box") << "toy_box_normal.png"
                                 << "toy_box_disp.png" << 0.5;
    }
    void normalOnlyGivesBackTheRelief() {
        QFETCH(QString, normal);
        QFETCH(QString, disp);
        QFETCH(double, least);
        QTemporaryDir dir;
        const std::string root = dir.path().toStdString();
        QVERIFY(fs::copy_file(learn(normal.toStdString()), root + "/panel_nrm.png"));
        Result<ImportedSet> set = importFolder(root);
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        QVERIFY(set->heightMissing);
        QVERIFY(deriveHeight(*set));
        QCOMPARE(set->material.normalGreen, NormalGreen::DirectX);
        const double r = correlation(set->assets.height, relief(learn(disp.toStdString()), true));
        qInfo("%s: derived height against the real depth map, r = %.3f", qPrintable(normal), r);
        QVERIFY2(r > least, qPrintable(QString::number(r)));
    }

    // graphics-snippets as shipped: a height map (white = high) in PNG and BMP, cone maps and a
    // colour texture under the author's own names.
    void graphicsSnippetsAsShipped() {
        const Result<ImportedSet> imported =
            importFolder(test::sharedTestData("graphics-snippets"));
        QVERIFY2(imported, imported ? "" : imported.error().message.c_str());
        const std::string report = reportOf(*imported);
        const Material& m = imported->material;
        QVERIFY2(endsWith(m.maps.height, "example_1_heightmap.png"), report.c_str());
        QVERIFY2(!m.heightIsDepth, report.c_str());
        QVERIFY2(worstDifference(imported->assets.height, relief(m.maps.height, false)) < 1e-6f,
                 report.c_str());
        QVERIFY2(report.find("Not used: example_1_heightmap.bmp") != std::string::npos,
                 report.c_str());
        for (const char* file : {"example_1_conemap.png", "example_1_texture.png"})
            QVERIFY2(report.find(file) != std::string::npos, report.c_str());
        // Its PNG and BMP are one name, not siblings confirming a glued tag ("textur" + "e").
        QVERIFY2(report.find("Ignored: example_1_texture.png (no map tag") != std::string::npos,
                 report.c_str());
    }
};

QTEST_GUILESS_MAIN(TextureSetConformanceTest)
#include "TextureSetConformanceTest.moc"

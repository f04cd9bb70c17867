// Batch export reads a folder as `import` and the editor do: texture sets named the way texture
// libraries, tools and engines name them, grouped by stem, each imported with the preset's
// settings (roles, packed channels, height or depth and green from the data); files of no set
// listed; a normal-only set and a broken file refused, naming them.

#include "parallax/export/BatchScan.h"

#include "ConventionSets.h"
#include "parallax/io/AtomicWrite.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>

using namespace px;
using namespace px::test;

namespace {

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

const BatchItem* itemNamed(const BatchFolder& folder, const std::string& name) {
    for (const BatchItem& item : folder.items) {
        if (item.name == name)
            return &item;
    }
    return nullptr;
}

} // namespace

class BatchScanTest : public QObject {
    Q_OBJECT

private slots:
    void setsNamedAsArtistsNameThem_data();
    void setsNamedAsArtistsNameThem();
    void normalOnlyAndBrokenSetsAreRefusedNamingThem();
    void nothingRecognisedIsRefusedWithTheReport();
    void missingFolder();
};

void BatchScanTest::setsNamedAsArtistsNameThem_data() {
    QTest::addColumn<unsigned>("seed");
    for (unsigned seed : {1u, 2u, 6u})
        QTest::addRow("seed%u", seed) << seed;
}

void BatchScanTest::setsNamedAsArtistsNameThem() {
    QFETCH(unsigned, seed);
    QTemporaryDir dir;
    const std::string root = dir.path().toStdString();
    using T = Texels;
    const NormalGreen gl = NormalGreen::OpenGL, dx = NormalGreen::DirectX;
    // Poly Haven (a spare DirectX normal map, a specular map), in textures/ as downloaded.
    std::filesystem::create_directory(root + "/textures");
    writeConventionSet(root + "/textures",
                       {{"rock_face_diff_1k.jpg", T::Albedo},
                        {"rock_face_nor_gl_1k.png", T::Normal},
                        {"rock_face_disp_1k.png", T::Height},
                        {"rock_face_spec_1k.png", T::Grey},
                        {"rock_face_arm_1k.png", T::Packed}},
                       seed, gl);
    writeConventionSet(root + "/textures", {{"rock_face_nor_dx_1k.png", T::Normal}}, seed, dx);
    // ambientCG, with DirectX green by name and a depth map its data gives away.
    const NormalGreen ambientGreen = seed % 2 ? gl : dx;
    writeConventionSet(
        root,
        {{"Bricks076C_1K-PNG_Color.png", T::Albedo},
         {ambientGreen == gl ? "Bricks076C_1K-PNG_NormalGL.png" : "Bricks076C_1K-PNG_NormalDX.png",
          T::Normal},
         {"Bricks076C_1K-PNG_Displacement.png", T::Depth}},
        seed + 1, ambientGreen);
    // Tags glued to the stem, an Unreal ORM set, and the old batch suffixes.
    writeConventionSet(
        root,
        {{"stone01.jpg", T::Albedo}, {"stone01z.png", T::Height}, {"stone01n.png", T::Normal}},
        seed + 2, seed % 3 ? gl : dx);
    writeConventionSet(root,
                       {{"T_Crate_BaseColor.png", T::Albedo},
                        {"T_Crate_Normal_DirectX.png", T::Normal},
                        {"T_Crate_Height.png", T::Height},
                        {"T_Crate_ORM.png", T::Packed}},
                       seed + 3, dx);
    writeConventionSet(root, {{"bricks_height.png", T::Height}, {"bricks_albedo.jpg", T::Albedo}},
                       seed + 4, gl);
    QVERIFY(writeTextFile(root + "/readme.txt", "from a library"));

    const Result<BatchFolder> folder = scanBatchFolder(root);
    QVERIFY2(folder, folder ? "" : folder.error().message.c_str());
    QStringList names;
    for (const BatchItem& item : folder->items)
        names << QString::fromStdString(item.name);
    QCOMPARE(names, (QStringList{"bricks", "Bricks076C", "rock_face", "stone01", "T_Crate"}));
    QCOMPARE(folder->unassigned.size(), std::size_t(1));
    QCOMPARE(fileName(folder->unassigned.front().path), std::string("readme.txt"));
    QCOMPARE(folder->unassigned.front().why, std::string("not an image file"));

    Material preset;
    preset.technique = Technique::Relief;
    preset.heightScale = 0.08f;
    preset.maps.albedo = "ignored.png";
    auto import = [&](const std::string& name) {
        const BatchItem* item = itemNamed(*folder, name);
        if (!item)
            qFatal("no item %s", name.c_str());
        Result<ImportedSet> set = importBatchItem(*item, preset);
        if (!set)
            qFatal("%s", set.error().message.c_str());
        return std::move(*set);
    };
    const ImportedSet rock = import("rock_face");
    QCOMPARE(fileName(rock.material.maps.normal), std::string("rock_face_nor_gl_1k.png"));
    QCOMPARE(fileName(rock.material.maps.height), std::string("rock_face_disp_1k.png"));
    QCOMPARE(fileName(rock.material.maps.specular), std::string("rock_face_spec_1k.png"));
    QCOMPARE(fileName(rock.material.maps.metallic), std::string("rock_face_arm_1k.png"));
    QVERIFY(rock.material.surface.metallic == HeightChannel::Blue);
    QVERIFY(rock.material.technique == Technique::Relief);
    QCOMPARE(rock.material.heightScale, 0.08f);

    const ImportedSet bricks076 = import("Bricks076C");
    QVERIFY(bricks076.material.heightIsDepth); // told by the normal map, not the name
    QCOMPARE(bricks076.material.normalGreen, ambientGreen);
    QCOMPARE(fileName(bricks076.material.maps.albedo), std::string("Bricks076C_1K-PNG_Color.png"));

    const ImportedSet stone = import("stone01");
    QCOMPARE(fileName(stone.material.maps.height), std::string("stone01z.png"));
    QCOMPARE(fileName(stone.material.maps.normal), std::string("stone01n.png"));
    QCOMPARE(stone.material.normalGreen, seed % 3 ? gl : dx);

    const ImportedSet crate = import("T_Crate");
    QCOMPARE(crate.material.normalGreen, dx);
    QVERIFY(crate.material.surface.roughness == HeightChannel::Green);
    QVERIFY(crate.material.lighting == LightingModel::MetallicRoughness);

    const ImportedSet bricks = import("bricks");
    QCOMPARE(fileName(bricks.material.maps.albedo), std::string("bricks_albedo.jpg"));
    QVERIFY(bricks.material.maps.normal.empty());
    QVERIFY(!bricks.material.heightIsDepth);
}

void BatchScanTest::normalOnlyAndBrokenSetsAreRefusedNamingThem() {
    QTemporaryDir dir;
    const std::string root = dir.path().toStdString();
    writeConventionSet(root, {{"tiles_normal.png", Texels::Normal}}, 3, NormalGreen::OpenGL);
    writeConventionSet(root, {{"wall_albedo.png", Texels::Albedo}}, 4, NormalGreen::OpenGL);
    QVERIFY(writeTextFile(root + "/wall_height.png", "not a png"));
    const Result<BatchFolder> folder = scanBatchFolder(root);
    QVERIFY2(folder, folder ? "" : folder.error().message.c_str());
    QCOMPARE(folder->items.size(), std::size_t(2));
    const Result<ImportedSet> tiles = importBatchItem(*itemNamed(*folder, "tiles"), {});
    QVERIFY(!tiles);
    QCOMPARE(QString::fromStdString(tiles.error().message),
             QString("the set tiles has only a normal map (tiles_normal.png), no height map to "
                     "export; `parallax-cli import --derive-height` makes one from it"));
    const Result<ImportedSet> wall = importBatchItem(*itemNamed(*folder, "wall"), {});
    QVERIFY(!wall);
    QVERIFY2(wall.error().message.starts_with(root + "/wall_height.png: "),
             wall.error().message.c_str());
}

void BatchScanTest::nothingRecognisedIsRefusedWithTheReport() {
    QTemporaryDir dir;
    const std::string root = dir.path().toStdString();
    QVERIFY(writeTextFile(root + "/notes.txt", "x"));
    QVERIFY(writeTextFile(root + "/IMG_0001.jpg", "x"));
    const Result<BatchFolder> folder = scanBatchFolder(root);
    QVERIFY(!folder);
    QCOMPARE(QString::fromStdString(folder.error().message),
             QString::fromStdString(root + ": no texture set recognised (no file named as a "
                                           "height, normal or colour map of a set)\n"
                                           "  IMG_0001.jpg: no map tag (_albedo, _disp, _normal, "
                                           "...), and not named after a set here\n"
                                           "  notes.txt: not an image file"));
}

void BatchScanTest::missingFolder() {
    const Result<BatchFolder> folder = scanBatchFolder("/no/such/folder");
    QVERIFY(!folder);
    QCOMPARE(QString::fromStdString(folder.error().message),
             QString("/no/such/folder: not a folder"));
}

QTEST_GUILESS_MAIN(BatchScanTest)
#include "BatchScanTest.moc"

// Loading and saving maps and materials: bad files change nothing and name themselves, saved
// materials reopen equal, maps are recognised by their suffix.

#include "model/MapLoading.h"

#include "model/MaterialSaver.h"
#include "model/SampleMaterial.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/material/MaterialFile.h"

#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <cmath>

using namespace px;
using namespace px::studio;

namespace {

std::string writeGrey(const QTemporaryDir& dir, const char* name, int w, int h, float value,
                      int channels = 1) {
    Image image(w, h, channels);
    for (float& p : image.pixels)
        p = value;
    std::string path = dir.filePath(name).toStdString();
    ImageWriteOptions options;
    options.format = PixelFormat::UInt16;
    if (!writeImage(path, image, options))
        return {};
    return path;
}

} // namespace

class MapLoadingTest : public QObject {
    Q_OBJECT
private slots:
    void suffixesNameMaps_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("kind");
        QTest::addColumn<bool>("depth");
        QTest::newRow("albedo") << "wall_albedo.png" << int(MapKind::Albedo) << false;
        QTest::newRow("basecolor") << "Wall_BaseColor.JPG" << int(MapKind::Albedo) << false;
        QTest::newRow("diffuse") << "wall-diffuse.tga" << int(MapKind::Albedo) << false;
        QTest::newRow("nrm") << "wall_nrm.png" << int(MapKind::Normal) << false;
        QTest::newRow("n") << "wall_n.png" << int(MapKind::Normal) << false;
        QTest::newRow("disp") << "bricks2_disp.jpg" << int(MapKind::Height) << false;
        QTest::newRow("depth") << "wall_depth.exr" << int(MapKind::Height) << true;
        QTest::newRow("h") << "wall_h.tif" << int(MapKind::Height) << false;
        QTest::newRow("cone") << "wall_cone.png" << int(MapKind::Cone) << false;
        QTest::newRow("relaxed") << "wall_relaxed_cone.png" << int(MapKind::RelaxedCone) << false;
        QTest::newRow("ao") << "wall_occlusion.png" << int(MapKind::Ao) << false;
        QTest::newRow("spec") << "wall_spec_2k.png" << int(MapKind::Specular) << false;
        QTest::newRow("REFL") << "wall_REFL.jpg" << int(MapKind::Specular) << false;
    }
    void suffixesNameMaps() {
        QFETCH(QString, file);
        QFETCH(int, kind);
        QFETCH(bool, depth);
        const auto match = mapKindFromFileName(file.toStdString());
        QVERIFY(match);
        QCOMPARE(int(match->kind), kind);
        QCOMPARE(match->depth, depth);
    }

    void unknownSuffixesAreNotGuessed() {
        QVERIFY(!mapKindFromFileName("photo.png"));
        QVERIFY(!mapKindFromFileName("bumpiness.png")); // ends in "ness", not a suffix word
        QVERIFY(!mapKindFromFileName("plan.png"));      // ends in "n" but not "_n"
    }

    void corruptFileChangesNothing() {
        QTemporaryDir dir;
        const std::string bad = dir.filePath("broken_height.png").toStdString();
        QVERIFY(writeTextFile(bad, "this is not a PNG"));
        const DocumentState state = makeSampleState(ProceduralMap::Bricks, 32);
        const Result<Loaded> loaded = loadMapFile(state, MapKind::Height, bad);
        QVERIFY(!loaded);
        QVERIFY2(loaded.error().message.find("broken_height.png") != std::string::npos,
                 loaded.error().message.c_str());
    }

    void coneMapMustMatchItsHeightMap() {
        QTemporaryDir dir;
        const DocumentState state = makeSampleState(ProceduralMap::Bricks, 32);
        const std::string wrongSize = writeGrey(dir, "small_cone.png", 16, 16, 0.5f, 3);
        Result<Loaded> loaded = loadMapFile(state, MapKind::Cone, wrongSize);
        QVERIFY(!loaded);
        QVERIFY(loaded.error().message.find("16x16") != std::string::npos);
        // Right size, but R is not this height map: baked from another one.
        Image other(32, 32, 3);
        const std::string otherPath = dir.filePath("other_cone.png").toStdString();
        QVERIFY(writeImage(otherPath, other, {PixelFormat::UInt16, false}));
        loaded = loadMapFile(state, MapKind::Cone, otherPath);
        QVERIFY(!loaded);
        QVERIFY(loaded.error().message.find("another height map") != std::string::npos);
    }

    void newHeightDropsConeMaps() {
        QTemporaryDir dir;
        DocumentState state = makeSampleState(ProceduralMap::Bricks, 32);
        auto assets = std::make_shared<MaterialAssets>(*state.assets);
        assets->cone = ConeMap(ConeKind::Conservative, 32, 32);
        state.assets = assets;
        state.setUnsaved(MapKind::Cone, true);
        const std::string flat = writeGrey(dir, "flat_height.png", 8, 8, 0.25f);
        const Result<Loaded> loaded = loadMapFile(state, MapKind::Height, flat);
        QVERIFY(loaded);
        QVERIFY(!loaded->state.hasMap(MapKind::Cone));
        QVERIFY(!loaded->state.isUnsaved(MapKind::Cone));
        QCOMPARE(loaded->state.assets->height.width, 8);
        QVERIFY(!loaded->notes.empty());
        // The input is untouched.
        QCOMPARE(state.assets->height.width, 32);
        QVERIFY(state.hasMap(MapKind::Cone));
    }

    void depthMapsLoadInverted() {
        QTemporaryDir dir;
        const std::string path = writeGrey(dir, "wall_depth.png", 4, 4, 0.25f);
        const Result<Loaded> loaded =
            loadMapFile(makeSampleState(ProceduralMap::Bricks, 8), MapKind::Height, path, true);
        QVERIFY(loaded);
        QVERIFY(std::abs(loaded->state.assets->height.at(1, 1) - 0.75f) < 1e-4f);
        QVERIFY(loaded->state.material.heightIsDepth);
    }

    // A float height map in its own units: read by its range, which the material records (and
    // keeps when the same file is read again), the message says; saved and reopened the same.
    void floatHeightInItsOwnUnitsIsReadByItsRange() {
        QTemporaryDir dir;
        Image bake(6, 4, 1);
        for (std::size_t i = 0; i < bake.pixels.size(); ++i)
            bake.pixels[i] = -2.5f + 0.25f * static_cast<float>(i); // -2.5 .. 3.25
        const std::string path = dir.filePath("wall_bake.exr").toStdString();
        QVERIFY(writeImage(path, bake, {PixelFormat::Float, false}));
        const DocumentState state = makeSampleState(ProceduralMap::Bricks, 8);
        const Result<Loaded> loaded = loadMapFile(state, MapKind::Height, path);
        QVERIFY2(loaded, loaded ? "" : loaded.error().message.c_str());
        const Material& m = loaded->state.material;
        QVERIFY((m.heightRange == HeightRange{-2.5f, 3.25f}));
        QCOMPARE(loaded->state.assets->height.at(0, 0), 0.0f);
        QCOMPARE(loaded->state.assets->height.at(5, 3), 1.0f);
        QVERIFY(std::abs(loaded->state.assets->height.at(1, 0) - 0.25f / 5.75f) < 1e-7f);
        QVERIFY(std::any_of(loaded->notes.begin(), loaded->notes.end(), [](const std::string& n) {
            return n.find("wall_bake.exr holds heights from -2.5 to 3.25") != std::string::npos;
        }));
        // Read again (depth ticked), the material's wider range is kept where the file fits it.
        DocumentState wider = loaded->state;
        wider.material.heightRange = HeightRange{-4.0f, 4.0f};
        const Result<Loaded> again = loadMapFile(wider, MapKind::Height, path, true);
        QVERIFY(again);
        QVERIFY((again->state.material.heightRange == HeightRange{-4.0f, 4.0f}));
        QCOMPARE(again->state.assets->height.at(0, 0), 1.0f - 1.5f / 8.0f);
        // Saved and reopened: the same heights.
        const std::string file = dir.filePath("wall.json").toStdString();
        const Result<DocumentState> saved = saveDocumentState(loaded->state, file);
        QVERIFY2(saved, saved ? "" : saved.error().message.c_str());
        const Result<Loaded> reopened = openMaterialFile(file);
        QVERIFY2(reopened, reopened ? "" : reopened.error().message.c_str());
        QVERIFY(reopened->state.material.heightRange == m.heightRange);
        for (std::size_t i = 0; i < bake.pixels.size(); ++i)
            QCOMPARE(reopened->state.assets->height.texels[i],
                     loaded->state.assets->height.texels[i]);
        // A PNG loaded after it drops the range.
        const std::string png = writeGrey(dir, "wall_height.png", 4, 4, 0.5f);
        const Result<Loaded> plain = loadMapFile(loaded->state, MapKind::Height, png);
        QVERIFY(plain && !plain->state.material.heightRange);
    }

    // A specular map loads into its slot as stored and is saved with the material.
    void specularMapIsKept() {
        QTemporaryDir dir;
        const std::string spec = writeGrey(dir, "wall_spec.png", 8, 8, 0.4f);
        const DocumentState state = makeSampleState(ProceduralMap::Bricks, 8);
        const Result<Loaded> loaded = loadMapFile(state, MapKind::Specular, spec);
        QVERIFY(loaded);
        QVERIFY(loaded->state.hasMap(MapKind::Specular));
        QVERIFY(std::abs(loaded->state.assets->specular.at(3, 3) - 0.4f) < 1e-4f);
        QCOMPARE(loaded->state.material.maps.specular, spec);
        const std::string file = dir.filePath("wall.json").toStdString();
        QVERIFY(saveDocumentState(loaded->state, file));
        const Result<Loaded> reopened = openMaterialFile(file);
        QVERIFY2(reopened, reopened ? "" : reopened.error().message.c_str());
        QVERIFY(reopened->state.hasMap(MapKind::Specular));
        QVERIFY(readTextFile(file)->find("\"specular\": \"wall_spec.png\"") != std::string::npos);
    }

    void sampleSavesAndReopensEqual() {
        QTemporaryDir dir;
        const std::string file = dir.filePath("sub/bricks.json").toStdString();
        QVERIFY(QDir().mkpath(dir.filePath("sub")));
        DocumentState state = makeSampleState(ProceduralMap::Bricks, 64);
        state.material.heightScale = 0.08f;
        const Result<DocumentState> saved = saveDocumentState(state, file);
        QVERIFY2(saved, saved ? "" : saved.error().message.c_str());
        QVERIFY(!saved->anyUnsaved());
        QVERIFY(QFile::exists(dir.filePath("sub/bricks_height.png")));
        QVERIFY(QFile::exists(dir.filePath("sub/bricks_albedo.png")));
        // Paths in the file are relative to it, so the folder can move.
        const Result<std::string> text = readTextFile(file);
        QVERIFY(text);
        QVERIFY(text->find("\"bricks_height.png\"") != std::string::npos);

        const Result<Loaded> reopened = openMaterialFile(file);
        QVERIFY2(reopened, reopened ? "" : reopened.error().message.c_str());
        const HeightField& a = state.assets->height;
        const HeightField& b = reopened->state.assets->height;
        QCOMPARE(b.width, a.width);
        float worst = 0.0f;
        for (std::size_t i = 0; i < a.texels.size(); ++i)
            worst = std::max(worst, std::abs(a.texels[i] - b.texels[i]));
        QVERIFY(worst <= 0.5f / 65535.0f + 1e-7f); // 16-bit PNG
        QCOMPARE(reopened->state.material.heightScale, 0.08f);
        QCOMPARE(reopened->state.assets->albedo.channels, 3);
    }

    void savedConeMapsNeverWiden() {
        QTemporaryDir dir;
        DocumentState state = makeSampleState(ProceduralMap::Rivets, 16);
        auto assets = std::make_shared<MaterialAssets>(*state.assets);
        assets->cone = ConeMap(ConeKind::Conservative, 16, 16);
        for (int i = 0; i < 256; ++i)
            assets->cone.sqrtRatio[static_cast<std::size_t>(i)] = 0.1234567f + i * 1e-4f;
        state.assets = assets;
        state.setUnsaved(MapKind::Cone, true);
        const std::string file = dir.filePath("r.json").toStdString();
        const Result<DocumentState> saved = saveDocumentState(state, file);
        QVERIFY(saved);
        const Result<Loaded> reopened = openMaterialFile(file);
        QVERIFY2(reopened, reopened ? "" : reopened.error().message.c_str());
        const ConeMap& cone = reopened->state.assets->cone;
        QCOMPARE(cone.width, 16);
        for (int i = 0; i < 256; ++i) {
            const float original = assets->cone.sqrtRatio[static_cast<std::size_t>(i)];
            QVERIFY(cone.sqrtRatio[static_cast<std::size_t>(i)] <= original);
            QVERIFY(cone.sqrtRatio[static_cast<std::size_t>(i)] > original - 2.0f / 65535.0f);
        }
    }

    // Save As onto one of the document's own map files (picked in the file dialog by mistake) is
    // refused, and the map stays as it was.
    void saveAsOntoAMapRefused() {
        QTemporaryDir dir;
        const std::string height = writeGrey(dir, "w_height.png", 8, 8, 0.5f);
        const Result<std::string> before = readTextFile(height, false);
        Result<Loaded> loaded =
            loadMapFile(makeSampleState(ProceduralMap::Bricks, 8), MapKind::Height, height);
        QVERIFY(loaded);
        const Result<DocumentState> saved = saveDocumentState(loaded->state, height);
        QVERIFY(!saved);
        QVERIFY2(saved.error().message.find("is the same file as") != std::string::npos,
                 saved.error().message.c_str());
        QCOMPARE(readTextFile(height, false).value(), before.value());
    }

    void relativePathsSurviveSaveAsElsewhere() {
        QTemporaryDir dir;
        QVERIFY(QDir().mkpath(dir.filePath("a/maps")));
        QVERIFY(QDir().mkpath(dir.filePath("b/deep")));
        const std::string height = writeGrey(dir, "a/maps/w_height.png", 8, 8, 0.5f);
        Result<Loaded> loaded =
            loadMapFile(makeSampleState(ProceduralMap::Bricks, 8), MapKind::Height, height);
        QVERIFY(loaded);
        const std::string first = dir.filePath("a/w.json").toStdString();
        Result<DocumentState> saved = saveDocumentState(loaded->state, first);
        QVERIFY(saved);
        const std::string second = dir.filePath("b/deep/w.json").toStdString();
        saved = saveDocumentState(*saved, second);
        QVERIFY(saved);
        const Result<Loaded> reopened = openMaterialFile(second);
        QVERIFY2(reopened, reopened ? "" : reopened.error().message.c_str());
        QCOMPARE(reopened->state.assets->height.width, 8);
        const Result<Material> raw = loadMaterial(second);
        QVERIFY(raw);
        QCOMPARE(QString::fromStdString(raw->maps.height), QString("../../a/maps/w_height.png"));
    }

    void folderImportFindsMapsByName() {
        QTemporaryDir dir;
        writeGrey(dir, "rock_disp.png", 8, 8, 0.5f);
        writeGrey(dir, "rock_color.png", 8, 8, 0.7f);
        writeGrey(dir, "notes.png", 8, 8, 0.1f);
        const Result<TextureSetPlan> found =
            planTextureSet(*folderFiles(dir.path().toStdString()), "dir");
        QVERIFY(found);
        QCOMPARE(found->files.size(), std::size_t(2));
        QCOMPARE(found->ignored.size(), std::size_t(1));
        Result<ImportedSet> set = importTextureSet(*found);
        QVERIFY(set);
        const DocumentState state = importedState(std::move(*set));
        QCOMPARE(state.assets->height.width, 8);
        QCOMPARE(state.assets->albedo.width, 8);
        QVERIFY(!state.isUnsaved(MapKind::Albedo) && !state.isUnsaved(MapKind::Height));
    }

    void folderImportIsAllOrNothing() {
        QTemporaryDir dir;
        writeGrey(dir, "rock_height.png", 8, 8, 0.5f);
        QVERIFY(writeTextFile(dir.filePath("rock_normal.png").toStdString(), "garbage"));
        const Result<TextureSetPlan> found =
            planTextureSet(*folderFiles(dir.path().toStdString()), "dir");
        QVERIFY(found);
        const Result<ImportedSet> set = importTextureSet(*found);
        QVERIFY(!set);
        QVERIFY(set.error().message.find("rock_normal.png") != std::string::npos);
    }

    void badMaterialFileNamesItself() {
        QTemporaryDir dir;
        const std::string file = dir.filePath("bad.json").toStdString();
        QVERIFY(writeTextFile(file, "{ \"format\": \"parallax-studio-material\", \"version\": 1, "
                                    "\"heigth\": {} }"));
        const Result<Loaded> loaded = openMaterialFile(file);
        QVERIFY(!loaded);
        QVERIFY(loaded.error().message.find("bad.json") != std::string::npos);
    }
};

QTEST_MAIN(MapLoadingTest)
#include "MapLoadingTest.moc"

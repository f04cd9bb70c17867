// Importing texture sets the test writes itself: every convention (height or depth, OpenGL or
// DirectX green, albedo with or without a suffix) over several seeds is read from the data; every
// file is assigned or listed with why; two sets are never mixed; failures name their file.

#include "parallax/material/TextureSetImport.h"

#include "TextureSets.h"
#include "parallax/io/AtomicWrite.h"

#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace px;
using namespace px::test;

namespace {

std::vector<std::string> filesOf(const QTemporaryDir& dir) {
    Result<std::vector<std::string>> files = folderFiles(dir.path().toStdString());
    return files ? *files : std::vector<std::string>{};
}

bool mentions(const std::vector<SkippedFile>& list, const std::string& file,
              const std::string& why) {
    return std::any_of(list.begin(), list.end(), [&](const SkippedFile& s) {
        return s.path.ends_with(file) && s.why.find(why) != std::string::npos;
    });
}

} // namespace

class TextureSetImportTest : public QObject {
    Q_OBJECT
private slots:
    void everyConventionIsToldFromTheData_data() {
        QTest::addColumn<bool>("depth");
        QTest::addColumn<bool>("directx");
        QTest::addColumn<bool>("albedoSuffix");
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {1u, 2u, 3u, 17u, 29u, 40u})
            for (bool depth : {false, true})
                for (bool directx : {false, true}) {
                    const bool suffix = (seed + (depth ? 1 : 0) + (directx ? 2 : 0)) % 2 == 0;
                    QTest::addRow("%s-%s-%s-seed%u", depth ? "depth" : "height",
                                  directx ? "directx" : "opengl", suffix ? "suffix" : "plain", seed)
                        << depth << directx << suffix << seed;
                }
    }
    void everyConventionIsToldFromTheData() {
        QFETCH(bool, depth);
        QFETCH(bool, directx);
        QFETCH(bool, albedoSuffix);
        QFETCH(unsigned, seed);
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "Wall" + std::to_string(seed);
        spec.depth = depth;
        spec.green = directx ? NormalGreen::DirectX : NormalGreen::OpenGL;
        spec.albedoSuffix = albedoSuffix;
        spec.seed = seed;
        const WrittenSet written = writeTextureSet(dir.path().toStdString(), spec);

        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        QVERIFY2(plan, plan ? "" : plan.error().message.c_str());
        QCOMPARE(plan->name, spec.stem);
        QCOMPARE(plan->assigned.size(), std::size_t(3));
        QVERIFY(plan->ignored.empty() && plan->duplicates.empty());
        QVERIFY(plan->find(MapKind::Albedo));
        QCOMPARE(plan->find(MapKind::Albedo)->path, written.albedoFile);

        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        QVERIFY(set->relief.fromData);
        QCOMPARE(set->material.heightIsDepth, depth);
        QCOMPARE(set->material.normalGreen, spec.green);
        QCOMPARE(set->material.normalSource, NormalSource::Map);
        QCOMPARE(set->material.name, spec.stem);
        QVERIFY2(set->relief.score > 0.8, set->relief.summary.c_str());
        // The material holds the height written, white = high, at every texel (16-bit file).
        QCOMPARE(set->assets.height.width, written.height.width);
        float worst = 0.0f;
        for (std::size_t i = 0; i < written.height.texels.size(); ++i)
            worst =
                std::max(worst, std::abs(set->assets.height.texels[i] - written.height.texels[i]));
        QVERIFY2(worst <= 1.0f / 65535.0f, QByteArray::number(worst));
        QVERIFY(!set->assets.normal.empty() && !set->assets.albedo.empty());
    }

    void withoutANormalMapTheNameDecidesAndSaysSo() {
        for (bool depth : {false, true}) {
            QTemporaryDir dir;
            TextureSetSpec spec;
            spec.normal = false;
            spec.depth = depth;
            spec.heightSuffix = depth ? "_depth" : "_height";
            writeTextureSet(dir.path().toStdString(), spec);
            const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
            QVERIFY(plan);
            const Result<ImportedSet> set = importTextureSet(*plan);
            QVERIFY(set);
            QVERIFY(!set->relief.fromData);
            QCOMPARE(set->material.heightIsDepth, depth);
            QCOMPARE(set->material.normalSource, NormalSource::HeightCentral);
            QVERIFY(set->relief.summary.find("Guessed from the file name") != std::string::npos);
            QVERIFY(set->relief.summary.find("flip it") != std::string::npos);
        }
    }

    void anotherSetsNormalMapIsNotTrusted() {
        // The normal map of a random height field says nothing about this one: the name decides.
        QTemporaryDir dir, other;
        TextureSetSpec spec;
        spec.normal = false;
        spec.heightSuffix = "_depth";
        writeTextureSet(dir.path().toStdString(), spec);
        TextureSetSpec foreign;
        foreign.seed = 5;
        const WrittenSet written = writeTextureSet(other.path().toStdString(), foreign);
        const std::string normal = dir.filePath("rock_normal.png").toStdString();
        QVERIFY(QFile::copy(QString::fromStdString(written.normalFile),
                            QString::fromStdString(normal)));
        const Result<ImportedSet> set = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        QVERIFY2(!set->relief.fromData, set->relief.summary.c_str());
        QVERIFY(set->material.heightIsDepth);
        QVERIFY(set->relief.summary.find("do not follow") != std::string::npos);
    }

    void twoSetsAreNeverMixed() {
        QTemporaryDir dir;
        TextureSetSpec a;
        a.stem = "bricks2";
        a.albedoSuffix = false;
        writeTextureSet(dir.path().toStdString(), a);
        TextureSetSpec b;
        b.stem = "toy_box";
        b.seed = 2;
        writeTextureSet(dir.path().toStdString(), b);
        QVERIFY(writeTextFile(dir.filePath("README.md").toStdString(), "origin"));
        QVERIFY(writeTextFile(dir.filePath("wood.png").toStdString(), "not read"));

        const std::vector<std::string> files = filesOf(dir);
        QCOMPARE(textureSetNames(files), (std::vector<std::string>{"bricks2", "toy_box"}));
        const Result<TextureSetPlan> unchosen = planTextureSet(files, "dir");
        QVERIFY(!unchosen);
        QCOMPARE(QString::fromStdString(unchosen.error().message),
                 QString("dir: holds 2 texture sets (bricks2, toy_box): choose one, they are "
                         "never mixed"));

        const Result<TextureSetPlan> plan = planTextureSet(files, "dir", "TOY_BOX");
        QVERIFY(plan);
        QCOMPARE(plan->name, std::string("toy_box"));
        QCOMPARE(plan->assigned.size(), std::size_t(3));
        for (const SetFile& f : plan->assigned)
            QVERIFY2(f.path.find("toy_box") != std::string::npos, f.path.c_str());
        // Every other file is listed with why.
        QCOMPARE(plan->assigned.size() + plan->ignored.size() + plan->duplicates.size(),
                 files.size());
        QVERIFY(mentions(plan->ignored, "bricks2_disp.png", "belongs to the set bricks2"));
        QVERIFY(mentions(plan->ignored, "bricks2.png", "the albedo of the set bricks2"));
        QVERIFY(mentions(plan->ignored, "README.md", "not an image file"));
        QVERIFY(mentions(plan->ignored, "wood.png", "no map suffix"));

        const Result<TextureSetPlan> none = planTextureSet(files, "dir", "stones");
        QVERIFY(!none);
        QCOMPARE(QString::fromStdString(none.error().message),
                 QString("dir: holds no texture set named 'stones' (it holds bricks2, toy_box)"));
    }

    void duplicatesAreListedAndTheSummaryNamesEveryFile() {
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.albedoSuffix = false;
        const WrittenSet written = writeTextureSet(dir.path().toStdString(), spec);
        QVERIFY(QFile::copy(QString::fromStdString(written.heightFile),
                            dir.filePath("rock_height.png")));
        QVERIFY(QFile::copy(QString::fromStdString(written.albedoFile),
                            dir.filePath("rock_color.png")));
        QVERIFY(writeTextFile(dir.filePath("notes.txt").toStdString(), "x"));
        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        QVERIFY(plan);
        // The suffixed albedo wins over the one named after the set; the first height file wins.
        QCOMPARE(plan->find(MapKind::Albedo)->path, dir.filePath("rock_color.png").toStdString());
        QCOMPARE(plan->find(MapKind::Height)->path, written.heightFile);
        QVERIFY(mentions(plan->duplicates, "rock.png", "a second albedo map: rock_color.png"));
        QVERIFY(
            mentions(plan->duplicates, "rock_height.png", "a second height map: rock_disp.png"));
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY(set);
        std::string text;
        for (const std::string& line : importSummary(*set))
            text += line + "\n";
        for (const char* name : {"rock_disp.png", "rock_normal.png", "rock_color.png", "rock.png",
                                 "rock_height.png", "notes.txt", "Told by the normal map"})
            QVERIFY2(text.find(name) != std::string::npos, (text + " lacks " + name).c_str());
        QVERIFY(text.find("Ignored: notes.txt (not an image file)") != std::string::npos);
    }

    void aBrokenFileFailsTheWholeImportNamingIt() {
        QTemporaryDir dir;
        writeTextureSet(dir.path().toStdString(), {});
        QVERIFY(writeTextFile(dir.filePath("rock_ao.png").toStdString(), "garbage"));
        const Result<ImportedSet> set = importTextureSet(*planTextureSet(filesOf(dir), "dir"));
        QVERIFY(!set);
        QVERIFY2(set.error().message.find("rock_ao.png") != std::string::npos,
                 set.error().message.c_str());
    }

    void aSetNeedsAHeightMap() {
        QTemporaryDir dir;
        QVERIFY(writeTextFile(dir.filePath("rock_albedo.png").toStdString(), "x"));
        const Result<TextureSetPlan> plan = planTextureSet(filesOf(dir), "dir");
        QVERIFY(plan);
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY(!set);
        QVERIFY(set.error().message.find("The texture set rock has no height map") == 0);
        const Result<TextureSetPlan> empty = planTextureSet({"/x/notes.txt"}, "x");
        QVERIFY(!empty);
        QVERIFY(empty.error().message.find("x: no image whose name ends in a map suffix") == 0);
    }
};

QTEST_GUILESS_MAIN(TextureSetImportTest)
#include "TextureSetImportTest.moc"

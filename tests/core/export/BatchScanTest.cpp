// Batch export's scan: height maps found by suffix, their siblings paired by base name, the
// preset applied, depth maps marked, duplicates reported.

#include "parallax/export/BatchScan.h"

#include "parallax/io/AtomicWrite.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace px;

class BatchScanTest : public QObject {
    Q_OBJECT

private slots:
    void findsHeightMapsAndSiblings();
    void missingFolder();

private:
    QTemporaryDir m_dir;
};

void BatchScanTest::findsHeightMapsAndSiblings() {
    QVERIFY(m_dir.isValid());
    // Only names matter to the scan: the files need not be images.
    for (const char* name :
         {"bricks_height.png", "bricks_albedo.jpg", "bricks_normal.png", "bricks_roughness.png",
          "Stones_DEPTH.tif", "stones_Color.png", "stones_nrm.png", "rock_h.exr", "rock_height.png",
          "notes_height.txt", "wall_displacement.exr", "wall_ao.png"}) {
        QVERIFY(writeTextFile(m_dir.filePath(name).toStdString(), "x").ok());
    }
    Material preset;
    preset.technique = Technique::Relief;
    preset.heightScale = 0.08f;
    preset.maps.albedo = "ignored.png";
    Result<std::vector<BatchItem>> items = scanBatchFolder(m_dir.path().toStdString(), preset);
    QVERIFY2(items.ok(), items.ok() ? "" : items.error().message.c_str());
    QStringList names;
    for (const BatchItem& item : *items)
        names << QString::fromStdString(item.name) + (item.problem.empty() ? "" : "!");
    // Sorted by file name; the text file is not an image; rock has two height maps.
    QCOMPARE(names, (QStringList{"Stones", "bricks", "rock", "rock!", "wall"}));
    auto file = [&](const std::string& path) {
        return QString::fromStdString(std::filesystem::path(path).filename().string());
    };
    const BatchItem& stones = (*items)[0];
    QVERIFY(stones.material.heightIsDepth); // _depth: white = deep
    QCOMPARE(file(stones.material.maps.albedo), QString("stones_Color.png"));
    QCOMPARE(file(stones.material.maps.normal), QString("stones_nrm.png"));
    const BatchItem& bricks = (*items)[1];
    QVERIFY(!bricks.material.heightIsDepth);
    QCOMPARE(QString::fromStdString(bricks.material.name), QString("bricks"));
    QCOMPARE(file(bricks.material.maps.albedo), QString("bricks_albedo.jpg"));
    QCOMPARE(file(bricks.material.maps.roughness), QString("bricks_roughness.png"));
    QVERIFY(bricks.material.maps.metallic.empty());
    QVERIFY(std::filesystem::path(bricks.material.maps.height).is_absolute());
    QVERIFY(bricks.material.technique == Technique::Relief);
    QCOMPARE(bricks.material.heightScale, 0.08f);
    QVERIFY((*items)[3].problem.find("a second height map for \"rock\"") != std::string::npos);
    QCOMPARE(file((*items)[4].material.maps.ao), QString("wall_ao.png"));
    QVERIFY((*items)[4].material.maps.albedo.empty()); // the preset's maps are not inherited
}

void BatchScanTest::missingFolder() {
    Result<std::vector<BatchItem>> items = scanBatchFolder("/no/such/folder", Material{});
    QVERIFY(!items.ok());
    QCOMPARE(QString::fromStdString(items.error().message),
             QString("/no/such/folder: no such folder"));
}

QTEST_GUILESS_MAIN(BatchScanTest)
#include "BatchScanTest.moc"

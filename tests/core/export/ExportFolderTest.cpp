// The export folder: built beside the target and moved in whole; never replaces a folder without
// --force, nor a folder of someone else's files even with it; updates an earlier export in place.

#include "parallax/export/ExportFolder.h"

#include "parallax/io/AtomicWrite.h"

#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>

using namespace px;
namespace fs = std::filesystem;

class ExportFolderTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        m_dir.reset(new QTemporaryDir);
        QVERIFY(m_dir->isValid());
    }
    void createsParentsAndCommits();
    void abandonedExportLeavesNothing();
    void existingFolderNeedsForce();
    void forceReplacesAPreviousExport();
    void aPlantedMarkerDecidesNoDeletion();
    void forceNeverReplacesForeignFiles();
    void forceKeepsFilesNoExportWrote();
    void emptyFolderIsReplacedWithoutForce();
    void fileInTheWayRefused();

private:
    fs::path path(const char* name) const { return fs::path(m_dir->path().toStdString()) / name; }
    // Every entry of the temporary folder, hidden ones included.
    QStringList entries() const {
        QStringList list;
        for (const auto& e : fs::directory_iterator(m_dir->path().toStdString()))
            list << QString::fromStdString(e.path().filename().string());
        list.sort();
        return list;
    }
    std::unique_ptr<QTemporaryDir> m_dir;
};

void ExportFolderTest::createsParentsAndCommits() {
    Result<ExportFolder> folder = ExportFolder::begin(path("a/b/out/"), false);
    QVERIFY2(folder.ok(), folder.ok() ? "" : folder.error().message.c_str());
    QVERIFY(!fs::exists(path("a/b/out"))); // nothing visible until commit
    QVERIFY(writeTextFile(folder->pathFor("x.txt"), "x").ok());
    folder->add("x.txt");
    Result<ExportFolder::Committed> files = folder->commit("test");
    QVERIFY(files.ok());
    QCOMPARE(files->files.size(), std::size_t(1));
    QCOMPARE(*readTextFile(path("a/b/out/x.txt").string()), std::string("x"));
    const std::string marker = *readTextFile((path("a/b/out") / kExportMarker).string());
    QVERIFY(marker.find("test\nx.txt\n") != std::string::npos);
    QCOMPARE(entries(), QStringList{"a"});
    QCOMPARE(std::distance(fs::directory_iterator(path("a/b")), fs::directory_iterator()), 1);
}

void ExportFolderTest::abandonedExportLeavesNothing() {
    {
        Result<ExportFolder> folder = ExportFolder::begin(path("out"), false);
        QVERIFY(folder.ok());
        QVERIFY(writeTextFile(folder->pathFor("half.txt"), "x").ok());
    } // an error path: never committed
    QVERIFY(entries().isEmpty());
}

void ExportFolderTest::existingFolderNeedsForce() {
    fs::create_directories(path("out"));
    QVERIFY(writeTextFile(path("out/mine.txt").string(), "keep").ok());
    Result<ExportFolder> folder = ExportFolder::begin(path("out"), false);
    QVERIFY(!folder.ok());
    QCOMPARE(QString::fromStdString(folder.error().message),
             QString::fromStdString(path("out").string() +
                                    ": already exists; use --force to replace it"));
    QCOMPARE(*readTextFile(path("out/mine.txt").string()), std::string("keep"));
    QCOMPARE(entries(), QStringList{"out"});
}

void ExportFolderTest::forceReplacesAPreviousExport() {
    for (const char* name : {"first.txt", "second.txt"}) {
        Result<ExportFolder> folder = ExportFolder::begin(path("out"), true);
        QVERIFY2(folder.ok(), folder.ok() ? "" : folder.error().message.c_str());
        QVERIFY(writeTextFile(folder->pathFor(name), name).ok());
        folder->add(name);
        QVERIFY(folder->commit("test").ok());
    }
    // The earlier export's file is kept: the marker listing it is found on disk, never obeyed.
    QCOMPARE(*readTextFile(path("out/first.txt").string()), std::string("first.txt"));
    QVERIFY(fs::exists(path("out/second.txt")));
    QCOMPARE(entries(), QStringList{"out"}); // no staging or old folder left
}

// A marker is a file found on disk: one planted in a folder (an archive's leftover) listing the
// user's files makes --force remove none of them, whatever names it lists.
void ExportFolderTest::aPlantedMarkerDecidesNoDeletion() {
    fs::create_directories(path("out"));
    const std::vector<std::string> victims = {"notes.txt", "a.png", "README", ".bashrc"};
    std::string marker = "Written by Parallax Studio 0.1.0: planted\n";
    for (const std::string& name : victims) {
        QVERIFY(writeTextFile(path(("out/" + name).c_str()).string(), "the user's " + name).ok());
        marker += name + "\n";
    }
    QVERIFY(writeTextFile((path("out") / kExportMarker).string(), marker).ok());
    Result<ExportFolder> folder = ExportFolder::begin(path("out"), true);
    QVERIFY2(folder.ok(), folder.ok() ? "" : folder.error().message.c_str());
    QVERIFY(writeTextFile(folder->pathFor("b.png"), "new").ok());
    folder->add("b.png");
    Result<ExportFolder::Committed> committed = folder->commit("test");
    QVERIFY2(committed.ok(), committed.ok() ? "" : committed.error().message.c_str());
    for (const std::string& name : victims) {
        QCOMPARE(*readTextFile(path(("out/" + name).c_str()).string()), "the user's " + name);
        QVERIFY2(std::find(committed->kept.begin(), committed->kept.end(), name) !=
                     committed->kept.end(),
                 name.c_str());
    }
    QCOMPARE(*readTextFile(path("out/b.png").string()), std::string("new"));
}

// Engines keep their references to the textures in files beside them (Unity .meta, Godot
// .import): re-exporting updates the textures in place and keeps those, and says so.
void ExportFolderTest::forceKeepsFilesNoExportWrote() {
    auto exportOnce = [this](const std::string& contents) {
        Result<ExportFolder> folder = ExportFolder::begin(path("out"), true);
        if (!folder)
            return Result<ExportFolder::Committed>(folder.error());
        if (Status s = writeTextFile(folder->pathFor("a.png"), contents); !s)
            return Result<ExportFolder::Committed>(s.error());
        folder->add("a.png");
        return folder->commit("test");
    };
    QVERIFY(exportOnce("first").ok());
    QVERIFY(writeTextFile(path("out/a.png.meta").string(), "guid: 1234").ok());
    QVERIFY(writeTextFile(path("out/a.png.import").string(), "uid://x").ok());
    Result<ExportFolder::Committed> second = exportOnce("second");
    QVERIFY2(second.ok(), second.ok() ? "" : second.error().message.c_str());
    QCOMPARE(*readTextFile(path("out/a.png").string()), std::string("second"));
    QCOMPARE(*readTextFile(path("out/a.png.meta").string()), std::string("guid: 1234"));
    QCOMPARE(*readTextFile(path("out/a.png.import").string()), std::string("uid://x"));
    QCOMPARE(second->kept, (std::vector<std::string>{"a.png.import", "a.png.meta"}));
    QCOMPARE(entries(), QStringList{"out"});
}

void ExportFolderTest::forceNeverReplacesForeignFiles() {
    fs::create_directories(path("photos"));
    QVERIFY(writeTextFile(path("photos/holiday.jpg").string(), "precious").ok());
    Result<ExportFolder> folder = ExportFolder::begin(path("photos"), true);
    QVERIFY(!folder.ok());
    QVERIFY2(folder.error().message.find("holds files that no export wrote") != std::string::npos,
             folder.error().message.c_str());
    QCOMPARE(*readTextFile(path("photos/holiday.jpg").string()), std::string("precious"));
}

void ExportFolderTest::emptyFolderIsReplacedWithoutForce() {
    fs::create_directories(path("out"));
    Result<ExportFolder> folder = ExportFolder::begin(path("out"), false);
    QVERIFY(folder.ok());
    QVERIFY(writeTextFile(folder->pathFor("x.txt"), "x").ok());
    folder->add("x.txt");
    QVERIFY(folder->commit("test").ok());
    QVERIFY(fs::exists(path("out/x.txt")));
}

void ExportFolderTest::fileInTheWayRefused() {
    QVERIFY(writeTextFile(path("out").string(), "a file").ok());
    Result<ExportFolder> folder = ExportFolder::begin(path("out"), true);
    QVERIFY(!folder.ok());
    QVERIFY(folder.error().message.find("exists and is not a folder") != std::string::npos);
}

QTEST_GUILESS_MAIN(ExportFolderTest)
#include "ExportFolderTest.moc"

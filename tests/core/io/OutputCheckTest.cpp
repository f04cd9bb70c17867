// Outputs checked before any work: never an input (same path, another spelling, a hard link, a
// symbolic link), never a folder, never in a missing folder.

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace px;
namespace fs = std::filesystem;

class OutputCheckTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        m_dir.reset(new QTemporaryDir);
        QVERIFY(m_dir->isValid());
        QVERIFY(writeFileAtomically(path("h.png"), "height").ok());
    }
    void sameFileRefused_data();
    void sameFileRefused();
    void distinctFilesAccepted();
    void twoOutputsOneFileRefused();
    void folderAndMissingFolderRefused();

private:
    std::string path(const std::string& name) const {
        return (fs::path(m_dir->path().toStdString()) / name).string();
    }
    std::unique_ptr<QTemporaryDir> m_dir;
};

void OutputCheckTest::sameFileRefused_data() {
    QTest::addColumn<QString>("out");
    QTest::newRow("same path") << "h.png";
    QTest::newRow("dot segment") << "./sub/../h.png";
    QTest::newRow("hard link") << "link.png";
    QTest::newRow("symbolic link") << "symlink.png";
}

void OutputCheckTest::sameFileRefused() {
    QFETCH(QString, out);
    fs::create_directory(path("sub"));
    fs::create_hard_link(path("h.png"), path("link.png"));
    fs::create_symlink(path("h.png"), path("symlink.png"));
    const std::string output = path(out.toStdString());
    const Status s = checkOutputs({{"--out", output}}, {{"--height", path("h.png")}});
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(output + ": --out names the same file as --height " +
                                    path("h.png") +
                                    ": refusing to overwrite an input; choose another output"));
    QCOMPARE(*readTextFile(path("h.png")), std::string("height"));
}

void OutputCheckTest::distinctFilesAccepted() {
    QVERIFY(writeFileAtomically(path("twin.png"), "height").ok()); // same bytes, another file
    QVERIFY(checkOutputs({{"--out", path("twin.png")}, {"--plot", path("new.svg")}},
                         {{"--height", path("h.png")}})
                .ok());
}

void OutputCheckTest::twoOutputsOneFileRefused() {
    const Status s = checkOutputs({{"--out", path("a.csv")}, {"--plot", path("./a.csv")}}, {});
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(path("./a.csv") +
                                    ": --plot names the same file as --out; give each output "
                                    "its own"));
}

void OutputCheckTest::folderAndMissingFolderRefused() {
    fs::create_directory(path("dir"));
    Status s = checkOutputs({{"--out", path("dir")}}, {});
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(path("dir") + ": --out is a folder; give a file name"));
    s = checkOutputs({{"--out", path("none/x.png")}}, {});
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(path("none/x.png") + ": cannot create the file: the folder " +
                                    path("none") + " does not exist"));
}

QTEST_GUILESS_MAIN(OutputCheckTest)
#include "OutputCheckTest.moc"

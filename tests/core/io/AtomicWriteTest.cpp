// The checked writer: a full disk (injected at byte N) is an error naming the file and the
// reason, the previous file stays byte-identical and no temporary is left; the leftovers of a
// killed run are removed by the next write; registered temporaries go on removeTemporariesNow().

#include "parallax/io/AtomicWrite.h"

#include "parallax/io/Temporaries.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

using namespace px;
namespace fs = std::filesystem;

class AtomicWriteTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        m_dir.reset(new QTemporaryDir);
        QVERIFY(m_dir->isValid());
    }
    void cleanup() { ::unsetenv("PX_TEST_FAIL_WRITE_AT"); }
    void fullDiskKeepsThePreviousFile_data();
    void fullDiskKeepsThePreviousFile();
    void folderAsTargetRefused();
    void missingFolderNamed();
    void staleTemporariesOfDeadRunsRemoved();
    void registeredTemporariesRemovedNewestFirst();
    void cancelledKindSurvivesAPrefix();

private:
    std::string path(const char* name) const {
        return (fs::path(m_dir->path().toStdString()) / name).string();
    }
    QStringList entries() const {
        QStringList list;
        for (const auto& e : fs::directory_iterator(m_dir->path().toStdString()))
            list << QString::fromStdString(e.path().filename().string());
        list.sort();
        return list;
    }
    std::unique_ptr<QTemporaryDir> m_dir;
};

void AtomicWriteTest::fullDiskKeepsThePreviousFile_data() {
    QTest::addColumn<int>("failAt");
    for (int at : {0, 1, 4095, 4096, 50000, 99999})
        QTest::newRow(std::to_string(at).c_str()) << at;
}

void AtomicWriteTest::fullDiskKeepsThePreviousFile() {
    QFETCH(int, failAt);
    const std::string target = path("map.png");
    QVERIFY(writeFileAtomically(target, "previous").ok());
    ::setenv("PX_TEST_FAIL_WRITE_AT", std::to_string(failAt).c_str(), 1);
    const Status s = writeFileAtomically(target, std::string(100000, 'x'));
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(target + ": writing failed (No space left on device); the "
                                             "previous file, if any, is unchanged"));
    QCOMPARE(s.error().file, target);
    QCOMPARE(*readTextFile(target), std::string("previous"));
    QCOMPARE(entries(), QStringList{"map.png"});
    // One byte less than the limit fits.
    ::setenv("PX_TEST_FAIL_WRITE_AT", std::to_string(failAt).c_str(), 1);
    QVERIFY(writeFileAtomically(target, std::string(static_cast<std::size_t>(failAt), 'y')).ok());
    QCOMPARE(readTextFile(target)->size(), static_cast<std::size_t>(failAt));
}

void AtomicWriteTest::folderAsTargetRefused() {
    fs::create_directory(path("out.png"));
    const Status s = writeFileAtomically(path("out.png"), "x");
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(path("out.png") + ": is a folder; give a file name"));
    QCOMPARE(entries(), QStringList{"out.png"});
}

void AtomicWriteTest::missingFolderNamed() {
    const Status s = writeFileAtomically(path("no/such/x.csv"), "x");
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(path("no/such/x.csv") +
                                    ": cannot create the file: the folder " + path("no/such") +
                                    " does not exist"));
}

void AtomicWriteTest::staleTemporariesOfDeadRunsRemoved() {
    // A pid that has exited: a child that ends at once.
    const pid_t child = ::fork();
    if (child == 0)
        ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    const std::string dead = std::to_string(child);
    for (const std::string& name :
         {".map.png.tmp" + dead + "-0", ".map.png.export-tmp" + dead + "-3"})
        QVERIFY(writeFileAtomically(path(name.c_str()), "debris").ok());
    fs::create_directory(path((".out.export-old" + dead + "-1").c_str()));
    // Not leftovers: a live process's temporary, another file's, a look-alike name.
    const std::string live = ".map.png.tmp" + std::to_string(::getppid()) + "-0";
    for (const std::string& name : {live, std::string(".other.png.tmp") + dead + "-0",
                                    std::string(".map.png.tmpx-0"), std::string("map.png.tmp1-0")})
        QVERIFY(writeFileAtomically(path(name.c_str()), "keep").ok());

    QCOMPARE(removeStaleTemporaries(path("out")), 1);
    QVERIFY(writeFileAtomically(path("map.png"), "new").ok());
    QCOMPARE(entries(), (QStringList{QString::fromStdString(live), ".map.png.tmpx-0",
                                     QString::fromStdString(".other.png.tmp" + dead + "-0"),
                                     "map.png", "map.png.tmp1-0"}));
}

void AtomicWriteTest::registeredTemporariesRemovedNewestFirst() {
    fs::create_directory(path("staging"));
    TemporaryGuard folder{fs::path(path("staging"))};
    QVERIFY(writeFileAtomically(path("staging/a.png"), "a").ok());
    TemporaryGuard file{fs::path(path("staging/a.png"))};
    QVERIFY(writeFileAtomically(path("kept.png"), "k").ok()); // released once written
    removeTemporariesNow();
    QCOMPARE(entries(), QStringList{"kept.png"});
}

void AtomicWriteTest::cancelledKindSurvivesAPrefix() {
    const Error cancelled{"the bake was cancelled", ErrorKind::Cancelled, {}};
    const Error prefixed = cancelled.prefixed("relief: ");
    QVERIFY(prefixed.cancelled());
    QCOMPARE(QString::fromStdString(prefixed.message), QString("relief: the bake was cancelled"));
    QVERIFY(!fileError("x.png", "the bake was cancelled").cancelled()); // text is not the kind
    QCOMPARE(fileError("x.png", "gone").file, std::string("x.png"));
}

QTEST_GUILESS_MAIN(AtomicWriteTest)
#include "AtomicWriteTest.moc"

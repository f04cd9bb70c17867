// The checked writer: a full disk (injected at byte N) is an error naming the file and the
// reason, the previous file stays byte-identical and no temporary is left; the leftovers of a
// killed run are removed by the next write, and only those (a writer in another PID namespace is
// not taken for dead); registered temporaries go on removeTemporariesNow().

#include "parallax/io/AtomicWrite.h"

#include "parallax/io/Temporaries.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cstdlib>
#include <ctime>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
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
    void staleTemporariesOfDeadRunsRemoved_data();
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

namespace {

pid_t deadPid() { // a pid that has exited: a child that ends at once
    const pid_t child = ::fork();
    if (child == 0)
        ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

// Holds an flock on `path` as a live writer (here or in another container) does.
int holdLock(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0)
        ::flock(fd, LOCK_SH);
    return fd;
}

void makeOld(const std::string& path) {
    const timespec times[2] = {{std::time(nullptr) - 7200, 0}, {std::time(nullptr) - 7200, 0}};
    ::utimensat(AT_FDCWD, path.c_str(), times, AT_SYMLINK_NOFOLLOW);
}

} // namespace

void AtomicWriteTest::staleTemporariesOfDeadRunsRemoved_data() {
    QTest::addColumn<QString>("name"); // DEAD: a dead pid, LIVE: a live one, HOST: ours
    QTest::addColumn<bool>("locked");  // a writer holds its lock
    QTest::addColumn<bool>("old");     // unchanged for two hours
    QTest::addColumn<bool>("removed");
    QTest::newRow("our host, dead, free") << ".out.tmpDEAD-0.HOST" << false << false << true;
    QTest::newRow("our host, dead, a folder")
        << ".out.export-tmpDEAD-3.HOST/" << false << false << true;
    QTest::newRow("our host, dead, a frames stage")
        << ".out.set-tmpDEAD-1.HOST/" << false << false << true;
    QTest::newRow("our host, dead pid but locked (an inherited descriptor)")
        << ".out.tmpDEAD-0.HOST" << true << false << false;
    QTest::newRow("our host, live") << ".out.tmpLIVE-0.HOST" << false << false << false;
    QTest::newRow("another container, writing")
        << ".out.tmpDEAD-0.0badf00d" << true << true << false;
    QTest::newRow("another container, free but recent")
        << ".out.tmpDEAD-0.0badf00d" << false << false << false;
    QTest::newRow("another container, free and old beyond doubt")
        << ".out.tmpDEAD-0.0badf00d" << false << true << true;
    QTest::newRow("an older version's, recent") << ".out.tmpDEAD-0" << false << false << false;
    QTest::newRow("an older version's, old") << ".out.export-oldDEAD-1/" << false << true << true;
    QTest::newRow("another file's") << ".other.tmpDEAD-0.HOST" << false << true << false;
    QTest::newRow("a look-alike") << ".out.tmpx-0.HOST" << false << true << false;
    QTest::newRow("not hidden") << "out.tmpDEAD-0.HOST" << false << true << false;
    QTest::newRow("a link named like one") << ".out.tmpDEAD-0.HOST@" << false << true << false;
}

// A leftover is removed only when its writer is provably gone: its lock free and, on this host,
// its pid gone; elsewhere (another PID namespace, where our pids mean nothing) only once it is
// old beyond doubt.
void AtomicWriteTest::staleTemporariesOfDeadRunsRemoved() {
    QFETCH(QString, name);
    QFETCH(bool, locked);
    QFETCH(bool, old);
    QFETCH(bool, removed);
    std::string entry = name.toStdString();
    const auto replace = [&](const std::string& from, const std::string& to) {
        if (const std::size_t at = entry.find(from); at != std::string::npos)
            entry.replace(at, from.size(), to);
    };
    replace("DEAD", std::to_string(deadPid()));
    replace("LIVE", std::to_string(::getppid()));
    replace("HOST", hostToken());
    const bool folder = entry.ends_with('/'), link = entry.ends_with('@');
    if (folder || link)
        entry.pop_back();
    if (folder) {
        fs::create_directory(path(entry.c_str()));
        QVERIFY(writeFileAtomically(path((entry + "/inside.png").c_str()), "debris").ok());
    } else if (link) {
        fs::create_symlink("map.png", path(entry.c_str()));
    } else {
        QVERIFY(writeFileAtomically(path(entry.c_str()), "debris").ok());
    }
    const int fd = locked ? holdLock(path(entry.c_str())) : -1;
    if (old)
        makeOld(path(entry.c_str()));
    QCOMPARE(removeStaleTemporaries(path("out")), removed ? 1 : 0);
    QCOMPARE(fs::exists(fs::symlink_status(path(entry.c_str()))), !removed);
    if (fd >= 0)
        ::close(fd);
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

// The checked writer: a full disk (injected at byte N) is an error naming the file and the
// reason, the previous file stays byte-identical and no temporary is left; the leftovers of a
// killed run are removed by the next write, and only those of the shape a writer makes with their
// lock free (anything else named like one is left alone); any legal name has its temporaries; a
// batch is all or nothing; registered temporaries go on removeTemporariesNow().

#include "parallax/io/AtomicWrite.h"

#include "parallax/io/StagedSet.h"
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
    void cleanup() { setTestHooks({}); }
    void fullDiskKeepsThePreviousFile_data();
    void fullDiskKeepsThePreviousFile();
    void folderAsTargetRefused();
    void missingFolderNamed();
    void staleTemporariesOfDeadRunsRemoved_data();
    void staleTemporariesOfDeadRunsRemoved();
    void longNamesHaveTemporaries_data();
    void longNamesHaveTemporaries();
    void batchIsAllOrNothing();
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
    TestHooks hooks;
    hooks.failWriteAt = failAt;
    setTestHooks(hooks);
    const Status s = writeFileAtomically(target, std::string(100000, 'x'));
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(target + ": writing failed (No space left on device); the "
                                             "previous file, if any, is unchanged"));
    QCOMPARE(s.error().file, target);
    QCOMPARE(*readTextFile(target), std::string("previous"));
    QCOMPARE(entries(), QStringList{"map.png"});
    // One byte less than the limit fits.
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

// Holds an flock on `path` as a live writer does.
int holdLock(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0)
        ::flock(fd, LOCK_SH);
    return fd;
}

void makeOld(const std::string& path) { // as an archive extracts it
    const timespec times[2] = {{86400, 0}, {86400, 0}};
    ::utimensat(AT_FDCWD, path.c_str(), times, AT_SYMLINK_NOFOLLOW);
}

} // namespace

void AtomicWriteTest::staleTemporariesOfDeadRunsRemoved_data() {
    QTest::addColumn<QString>("kind");   // tmp, stage, or the name itself
    QTest::addColumn<QString>("inside"); // for a stage: what it holds (file, link, folder, fifo,
                                         // hardlink), comma-separated
    QTest::addColumn<bool>("locked");    // a writer holds its lock
    QTest::addColumn<bool>("removed");
    QTest::newRow("a file, free") << "tmp"
                                  << "" << false << true;
    QTest::newRow("a file, held") << "tmp"
                                  << "" << true << false;
    QTest::newRow("a stage of files, free") << "stage"
                                            << "file,file" << false << true;
    QTest::newRow("an empty stage, free") << "stage"
                                          << "" << false << true;
    QTest::newRow("a stage of files, held") << "stage"
                                            << "file" << true << false;
    QTest::newRow("a stage holding a link") << "stage"
                                            << "file,link" << false << false;
    QTest::newRow("a stage holding a folder") << "stage"
                                              << "folder" << false << false;
    QTest::newRow("a stage holding a FIFO") << "stage"
                                            << "fifo" << false << false;
    QTest::newRow("a stage holding a hard link") << "stage"
                                                 << "hardlink" << false << false;
    QTest::newRow("a link named like a file") << "tmp-link"
                                              << "" << false << false;
    QTest::newRow("a link named like a stage") << "stage-link"
                                               << "" << false << false;
    QTest::newRow("a folder named like a file") << "tmp-folder"
                                                << "" << false << false;
    QTest::newRow("another target's") << ".px-tmp-0123456789abcdef-0123456789abcdef"
                                      << "" << false << false;
    QTest::newRow("a look-alike") << "tmp-short"
                                  << "" << false << false;
    QTest::newRow("an older version's journal stage") << ".out.export-tmp123-0.0badf00d"
                                                      << "file" << false << false;
}

// A leftover is removed only when it is provably a dead writer's: the shape a writer makes (a
// regular file, or a folder of regular files with one link each, owned by us) and its lock free.
// Its age says nothing (an archive's timestamps are anything): every case is made old.
void AtomicWriteTest::staleTemporariesOfDeadRunsRemoved() {
    QFETCH(QString, kind);
    QFETCH(QString, inside);
    QFETCH(bool, locked);
    QFETCH(bool, removed);
    QVERIFY(writeFileAtomically(path("victim.png"), "someone's").ok());
    std::string entry = kind.toStdString();
    const std::string base = kind.section('-', 0, 0).toStdString();
    if (base == "tmp" || base == "stage") {
        entry = temporaryName("out", base.c_str());
        if (kind.endsWith("-short"))
            entry.pop_back();
    }
    const std::string at = path(entry.c_str());
    if (kind.endsWith("-link")) {
        fs::create_symlink(path("victim.png"), at);
    } else if (kind == "stage" || kind.endsWith("-folder") || entry.find(".out.") == 0) {
        fs::create_directory(at);
        int n = 0;
        for (const QString& what : inside.split(',', Qt::SkipEmptyParts)) {
            const std::string in = at + "/f" + std::to_string(n++);
            if (what == "file")
                QVERIFY(writeFileAtomically(in, "debris").ok());
            else if (what == "link")
                fs::create_symlink(path("victim.png"), in);
            else if (what == "folder")
                fs::create_directory(in);
            else if (what == "fifo")
                QCOMPARE(::mkfifo(in.c_str(), 0600), 0);
            else if (what == "hardlink")
                fs::create_hard_link(path("victim.png"), in);
        }
    } else {
        QVERIFY(writeFileAtomically(at, "debris").ok());
    }
    const int fd = locked ? holdLock(at) : -1;
    makeOld(at);
    QCOMPARE(removeStaleTemporaries(path("out")), removed ? 1 : 0);
    QCOMPARE(fs::exists(fs::symlink_status(at)), !removed);
    QCOMPARE(*readTextFile(path("victim.png"), false), std::string("someone's"));
    if (fd >= 0)
        ::close(fd);
}

void AtomicWriteTest::longNamesHaveTemporaries_data() {
    QTest::addColumn<int>("bytes");
    for (int n : {200, 230, 250, 255})
        QTest::newRow(std::to_string(n).c_str()) << n;
}

// Every legal name (up to NAME_MAX) is written, replaced and locked; its temporaries' names do
// not grow with it. Non-UTF-8 bytes are only bytes.
void AtomicWriteTest::longNamesHaveTemporaries() {
    QFETCH(int, bytes);
    std::string name(static_cast<std::size_t>(bytes) - 4, 'n');
    name[3] = '\xe9'; // Latin-1, not UTF-8
    name += ".png";
    QVERIFY(writeFileAtomically(path(name.c_str()), "first").ok());
    QVERIFY(writeFileAtomically(path(name.c_str()), "second").ok());
    QCOMPARE(*readTextFile(path(name.c_str())), std::string("second"));
    QVERIFY(temporaryName(name, "stage").size() < 64);
    {
        Result<StagedSet> set = StagedSet::begin(path("."), name);
        QVERIFY2(set.ok(), set ? "" : set.error().message.c_str());
        QVERIFY(writeFileAtomically(set->pathFor(name), "third").ok());
        StagedSet::Update update;
        update.moves = {name};
        QVERIFY(set->commit(update).ok());
    }
    QCOMPARE(*readTextFile(path(name.c_str())), std::string("third"));
    QCOMPARE(entries().size(), 1);
}

// A batch's files are renamed only at its commit; one that ends uncommitted leaves every target
// as it was and no temporary.
void AtomicWriteTest::batchIsAllOrNothing() {
    QVERIFY(writeFileAtomically(path("a.csv"), "old a").ok());
    {
        OutputBatch batch;
        QVERIFY(writeFileAtomically(path("a.csv"), "new a").ok());
        QCOMPARE(*readTextFile(path("a.csv")), std::string("old a"));
        TestHooks hooks;
        hooks.failWriteAt = 2;
        setTestHooks(hooks);
        QVERIFY(!writeFileAtomically(path("b.svg"), "new b").ok()); // the second fails
        setTestHooks({});
    }
    QCOMPARE(*readTextFile(path("a.csv")), std::string("old a"));
    QCOMPARE(entries(), QStringList{"a.csv"});
    {
        OutputBatch batch;
        QVERIFY(writeFileAtomically(path("a.csv"), "new a").ok());
        QVERIFY(writeFileAtomically(path("b.svg"), "new b").ok());
        QVERIFY(batch.commit().ok());
    }
    QCOMPARE(*readTextFile(path("a.csv")), std::string("new a"));
    QCOMPARE(entries(), (QStringList{"a.csv", "b.svg"}));
}

void AtomicWriteTest::registeredTemporariesRemovedNewestFirst() {
    Result<StagedSet> set = StagedSet::begin(path("."), "out");
    QVERIFY(set.ok());
    QVERIFY(writeFileAtomically(set->pathFor("a.png"), "a").ok());
    QVERIFY(writeFileAtomically(set->pathFor("b.png"), "b").ok());
    const TemporaryGuard file{fs::path(path("plot.svg.part"))};
    QVERIFY(writeFileAtomically(path("plot.svg.part"), "p").ok());
    QVERIFY(writeFileAtomically(path("kept.png"), "k").ok()); // released once written
    removeTemporariesNow(); // the stage with its files, then the guarded file
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

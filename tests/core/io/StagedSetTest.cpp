// Sets of files written as one: a stage moved into place as a folder, or its files moved among
// others; a refusal before the first move changes nothing; a run killed half-way through the moves
// leaves whole files and a stage that the next run removes, obeying nothing in it; one writer at a
// time (OutputLock).

#include "parallax/io/StagedSet.h"

#include "parallax/image/ImageSet.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"
#include "parallax/io/OutputLock.h"
#include "parallax/io/Temporaries.h"

#include <QTemporaryDir>
#include <QtTest>
#include <csignal>
#include <cstdlib>
#include <string_view>
#include <sys/wait.h>
#include <unistd.h>

using namespace px;
namespace fs = std::filesystem;

class StagedSetTest : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup() { setTestHooks({}); }
    void newFolderMovedIntoPlace();
    void filesMovedAmongOthers();
    void inputAmongTheTargetsRefusedBeforeAnyMove();
    void killedHalfWayLeavesWholeFiles();
    void oneWriterAtATime();

private:
    std::string path(const std::string& name) const {
        return m_dir->filePath(QString::fromStdString(name)).toStdString();
    }
    std::string read(const std::string& name) const {
        Result<std::string> text = readTextFile(path(name), false);
        return text ? *text : std::string("<missing>");
    }
    QStringList hidden() const {
        return QDir(m_dir->path())
            .entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot)
            .filter(QRegularExpression("^\\."));
    }
    std::unique_ptr<QTemporaryDir> m_dir;
};

void StagedSetTest::init() {
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

void StagedSetTest::newFolderMovedIntoPlace() {
    Result<StagedSet> set = StagedSet::begin(path("out"), "out");
    QVERIFY(set.ok() && set->fresh());
    QVERIFY(writeFileAtomically(set->pathFor("a.txt"), "a").ok());
    QVERIFY(set->commit({}).ok());
    QCOMPARE(read("out/a.txt"), std::string("a"));
    QCOMPARE(hidden(), QStringList());
}

void StagedSetTest::filesMovedAmongOthers() {
    QVERIFY(writeFileAtomically(path("f-0.txt"), "old 0").ok());
    QVERIFY(writeFileAtomically(path("gone.txt"), "listed before").ok());
    QVERIFY(writeFileAtomically(path("mine.txt"), "the user's").ok());
    {
        Result<StagedSet> set = StagedSet::begin(m_dir->path().toStdString(), "f-0.txt");
        QVERIFY(set.ok() && !set->fresh());
        for (const char* name : {"f-0.txt", "f-1.txt"})
            QVERIFY(writeFileAtomically(set->pathFor(name), std::string("new ") + name).ok());
        StagedSet::Update update;
        update.moves = {"f-0.txt", "f-1.txt"};
        QVERIFY(set->commit(update).ok());
    }
    QCOMPARE(read("f-0.txt"), std::string("new f-0.txt"));
    QCOMPARE(read("f-1.txt"), std::string("new f-1.txt"));
    QCOMPARE(read("gone.txt"), std::string("listed before")); // nothing in the folder is removed
    QCOMPARE(read("mine.txt"), std::string("the user's"));
    QCOMPARE(hidden(), QStringList());
}

void StagedSetTest::inputAmongTheTargetsRefusedBeforeAnyMove() {
    for (const char* name : {"f-0.txt", "f-1.txt"})
        QVERIFY(writeFileAtomically(path(name), std::string("old ") + name).ok());
    fs::create_hard_link(path("f-1.txt"), path("input.txt"));
    const InputSession session; // after: files this run wrote itself are never inputs
    QVERIFY(InputFile::open(path("input.txt")).ok());
    {
        Result<StagedSet> set = StagedSet::begin(m_dir->path().toStdString(), "f-0.txt");
        QVERIFY(set.ok());
        for (const char* name : {"f-0.txt", "f-1.txt"})
            QVERIFY(writeFileAtomically(set->pathFor(name), "new").ok());
        StagedSet::Update update;
        update.moves = {"f-0.txt", "f-1.txt"};
        const Status done = set->commit(update);
        QVERIFY(!done.ok());
        QVERIFY2(done.error().message.find("f-1.txt: is the same file as") != std::string::npos,
                 done.error().message.c_str());
    }
    QCOMPARE(read("f-0.txt"), std::string("old f-0.txt"));
    QCOMPARE(read("f-1.txt"), std::string("old f-1.txt"));
    QCOMPARE(hidden(), QStringList());
}

// A child writes a set of four frames and is killed (SIGKILL, the test hook) after two moves:
// every frame is whole, old or new, and the stage is left; the next run removes the stage as a
// dead writer's (nothing in it is obeyed) and writes the set whole.
void StagedSetTest::killedHalfWayLeavesWholeFiles() {
    const std::vector<std::string> files = numberedFiles(path("t.png"), 4);
    const auto frame = [](float value) {
        return [value](int i) {
            Image image(2, 2, 1);
            for (float& v : image.pixels)
                v = value + 0.1f * static_cast<float>(i);
            return Result<Image>(image);
        };
    };
    QVERIFY(writeImageSet(files, frame(0.0f), {}).ok());
    std::vector<std::string> old;
    old.reserve(files.size());
    for (const std::string& f : files)
        old.push_back(readTextFile(f, false).value());
    const pid_t child = ::fork();
    if (child == 0) {
        TestHooks hooks;
        hooks.reached = [](const char* point) {
            if (std::string_view(point) == "frames-update")
                std::raise(SIGKILL);
        };
        setTestHooks(hooks);
        static_cast<void>(writeImageSet(files, frame(0.5f), {}));
        ::_exit(0); // not reached
    }
    int status = 0;
    QCOMPARE(::waitpid(child, &status, 0), child);
    QVERIFY(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    std::vector<std::string> expected;
    {
        QTemporaryDir clean;
        const std::vector<std::string> reference =
            numberedFiles(clean.filePath("t.png").toStdString(), 4);
        QVERIFY(writeImageSet(reference, frame(0.5f), {}).ok());
        for (const std::string& f : reference)
            expected.push_back(readTextFile(f, false).value());
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        const std::string now = readTextFile(files[i], false).value();
        QVERIFY2(now == (i < 2 ? expected[i] : old[i]), files[i].c_str()); // whole, in order
    }
    QCOMPARE(hidden().filter(QRegularExpression("^\\.px-stage-")).size(), 1);
    QVERIFY(writeImageSet(files, frame(0.5f), {}).ok());
    for (std::size_t i = 0; i < files.size(); ++i)
        QVERIFY2(readTextFile(files[i], false).value() == expected[i], files[i].c_str());
    QCOMPARE(hidden(), QStringList());
}

void StagedSetTest::oneWriterAtATime() {
    const std::string kLock = temporaryName("out", "lock");
    {
        Result<OutputLock> first = OutputLock::take(path("out"));
        QVERIFY(first.ok());
        QVERIFY(fs::exists(path(kLock)));
        const Result<OutputLock> second = OutputLock::take(path("out"));
        QVERIFY(!second.ok());
        QVERIFY2(second.error().message.find("another run (process " + std::to_string(::getpid()) +
                                             ") is writing it now") != std::string::npos,
                 second.error().message.c_str());
    }
    QVERIFY(!fs::exists(path(kLock))); // released and removed
    // A killed holder's file (the kernel dropped its lock) is taken, then removed.
    QVERIFY(writeFileAtomically(path(kLock), "12345\n").ok());
    { QVERIFY(OutputLock::take(path("out")).ok()); }
    QVERIFY(!fs::exists(path(kLock)));
    // Someone's file that bears the name is not a lock: refused, kept byte for byte.
    for (const std::string mine : {"notes\n", "12345", "12 34\n", "123456789012345678\n"}) {
        QVERIFY(writeFileAtomically(path(kLock), mine).ok());
        const Result<OutputLock> taken = OutputLock::take(path("out"));
        QVERIFY2(!taken.ok(), mine.c_str());
        QVERIFY2(taken.error().message.find("is a file that Parallax Studio did not write") !=
                     std::string::npos,
                 taken.error().message.c_str());
        QCOMPARE(read(kLock), mine);
    }
}

QTEST_GUILESS_MAIN(StagedSetTest)
#include "StagedSetTest.moc"

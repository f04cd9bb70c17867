// The record of a run's inputs and the gate every rename and delete goes through: an input is
// known by identity however it is spelt (hard link, "./sub/..", a link), a planned output met as
// an input is refused when it is met, a file the run wrote itself is not an input, special files
// are never waited on, replaced or deleted, and removals keep what is not the caller's.

#include "parallax/io/OutputGate.h"

#include "parallax/io/AtomicWrite.h"
#include "parallax/io/Inputs.h"

#include <QTemporaryDir>
#include <QtTest>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using namespace px;
namespace fs = std::filesystem;

class OutputGateTest : public QObject {
    Q_OBJECT

private slots:
    void init();
    void inputsKnownByIdentity_data();
    void inputsKnownByIdentity();
    void nothingRecordedOutsideASession();
    void plannedOutputRefusedWhenMetAsInput();
    void ownFilesAreNotInputs();
    void specialFilesNeverWaitedOn();
    void onlyRegularFilesReplaced_data();
    void onlyRegularFilesReplaced();
    void linkWrittenThrough();
    void removalsKeepWhatIsNotTheCallers();
    void eachThreadsRunHasItsOwnInputs();

private:
    std::string path(const std::string& name) const {
        return m_dir->filePath(QString::fromStdString(name)).toStdString();
    }
    std::unique_ptr<QTemporaryDir> m_dir;
};

void OutputGateTest::init() {
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    fs::create_directory(path("sub"));
    QVERIFY(writeFileAtomically(path("h.png"), "height").ok());
    fs::create_hard_link(path("h.png"), path("hard.png"));
    fs::create_symlink("h.png", path("link.png"));
}

void OutputGateTest::inputsKnownByIdentity_data() {
    QTest::addColumn<QString>("read");   // how the run named the input
    QTest::addColumn<QString>("target"); // how an output names it
    QTest::addColumn<QString>("reason");
    const QString input =
        "is the same file as [^ ]*h.png \\(the height map\\), which this run reads";
    QTest::newRow("same name") << "h.png"
                               << "h.png" << input;
    QTest::newRow("./sub/..") << "h.png"
                              << "sub/../h.png" << input;
    QTest::newRow("a hard link") << "h.png"
                                 << "hard.png" << input;
    QTest::newRow("read through a link")
        << "link.png"
        << "h.png"
        << "is the same file as [^ ]*link.png \\(the height map\\)";
    QTest::newRow("a link to it") << "h.png"
                                  << "link.png"
                                  << "is a symbolic link to [^ ]*h.png, which is the same file as";
}

void OutputGateTest::inputsKnownByIdentity() {
    QFETCH(QString, read);
    QFETCH(QString, target);
    QFETCH(QString, reason);
    const InputSession session;
    QVERIFY(InputFile::open(path(read.toStdString()), "the height map").ok());
    const Result<fs::path> s = outputTarget(path(target.toStdString()));
    QVERIFY(!s.ok());
    QVERIFY2(QString::fromStdString(s.error().message).contains(QRegularExpression(reason)),
             s.error().message.c_str());
    // The write itself is refused too, and leaves the input and nothing else.
    QVERIFY(!writeFileAtomically(path(target.toStdString()), "over").ok());
    QCOMPARE(readTextFile(path("h.png"), false).value(), std::string("height"));
    QCOMPARE(QDir(m_dir->path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
             (QStringList{"h.png", "hard.png", "link.png", "sub"}));
}

void OutputGateTest::nothingRecordedOutsideASession() {
    QVERIFY(InputFile::open(path("h.png")).ok());
    QVERIFY(checkReplaceable(path("h.png")).ok());
    {
        const InputSession session;
        QVERIFY(InputFile::open(path("h.png")).ok());
        QVERIFY(!checkReplaceable(path("hard.png")).ok());
    }
    QVERIFY(checkReplaceable(path("hard.png")).ok()); // the record ends with the session
}

void OutputGateTest::plannedOutputRefusedWhenMetAsInput() {
    {
        const InputSession session; // an input recorded first, then the output planned
        QVERIFY(noteInput(path("h.png"), "--height").ok());
        QVERIFY(!planOutput(path("hard.png"), "frame 0 of --turntable").ok());
    }
    const InputSession session;
    QVERIFY(planOutput(path("hard.png"), "--out").ok());
    const Status s = noteInput(path("h.png"), "the height map of m.json");
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString::fromStdString(path("hard.png") + ": --out names the same file as " +
                                    path("h.png") +
                                    " (the height map of m.json), which this run reads: "
                                    "refusing to overwrite an input; choose another output"));
    QVERIFY(noteInput(path("absent.png"), "a map").ok()); // nothing there: nothing to lose
}

void OutputGateTest::ownFilesAreNotInputs() {
    const InputSession session;
    QVERIFY(writeFileAtomically(path("made.svg"), "<svg/>").ok());
    QCOMPARE(readTextFile(path("made.svg")).value(), std::string("<svg/>"));
    QVERIFY(writeFileAtomically(path("made.svg"), "<svg></svg>").ok());
}

void OutputGateTest::specialFilesNeverWaitedOn() {
    QVERIFY(::mkfifo(path("pipe.png").c_str(), 0644) == 0);
    QElapsedTimer timer;
    timer.start();
    const Result<InputFile> file = InputFile::open(path("pipe.png"));
    QVERIFY(!file.ok());
    QVERIFY2(file.error().message.find("is a FIFO (named pipe), not a regular file") !=
                 std::string::npos,
             file.error().message.c_str());
    QVERIFY(!readTextFile(path("pipe.png")).ok());
    QVERIFY(!InputFile::open(path("sub")).ok());
    QVERIFY(!InputFile::open("/dev/null").ok());
    // A hang guard, not a speed target: opening with O_NONBLOCK returns at once.
    QVERIFY(timer.elapsed() < 5000);
}

void OutputGateTest::onlyRegularFilesReplaced_data() {
    QTest::addColumn<QString>("target");
    QTest::addColumn<QString>("reason");
    QTest::newRow("a FIFO") << "pipe.png"
                            << "is a FIFO \\(named pipe\\), not a regular file";
    QTest::newRow("a device") << "/dev/null"
                              << "is a character device, not a regular file";
    QTest::newRow("a folder") << "sub"
                              << "is a folder; give a file name";
    QTest::newRow("a link to a FIFO") << "piped.png"
                                      << "is a symbolic link to [^ ]*pipe.png, which is a FIFO";
    QTest::newRow("a dangling link") << "dangling.png"
                                     << "is a symbolic link \\(to none.png\\) to nothing that "
                                        "exists: refusing to create a file there";
}

void OutputGateTest::onlyRegularFilesReplaced() {
    QFETCH(QString, target);
    QFETCH(QString, reason);
    QVERIFY(::mkfifo(path("pipe.png").c_str(), 0644) == 0);
    fs::create_symlink("none.png", path("dangling.png"));
    fs::create_symlink("pipe.png", path("piped.png"));
    const std::string file =
        target.startsWith('/') ? target.toStdString() : path(target.toStdString());
    const Status s = writeFileAtomically(file, "x");
    QVERIFY(!s.ok());
    QVERIFY2(QString::fromStdString(s.error().message).contains(QRegularExpression(reason)),
             s.error().message.c_str());
    struct stat st {};
    QVERIFY(::lstat(path("pipe.png").c_str(), &st) == 0 && S_ISFIFO(st.st_mode));
    QVERIFY(::lstat(path("dangling.png").c_str(), &st) == 0 && S_ISLNK(st.st_mode));
    QVERIFY(::lstat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
}

// A single file named through a link: the link's target is replaced (atomically, its temporary
// beside it) and the link stays a link, as an editor saves a linked document.
void OutputGateTest::linkWrittenThrough() {
    fs::create_directory(path("shared"));
    QVERIFY(writeFileAtomically(path("shared/out.png"), "old").ok());
    fs::create_symlink("shared/out.png", path("out.png"));
    QVERIFY(writeFileAtomically(path("out.png"), "new").ok());
    QVERIFY(fs::is_symlink(path("out.png")));
    QCOMPARE(readTextFile(path("shared/out.png"), false).value(), std::string("new"));
    QCOMPARE(QDir(QString::fromStdString(path("shared")))
                 .entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
             QStringList{"out.png"});
}

void OutputGateTest::removalsKeepWhatIsNotTheCallers() {
    const InputSession session;
    QVERIFY(InputFile::open(path("h.png")).ok());
    QVERIFY(::mkfifo(path("pipe.png").c_str(), 0644) == 0);
    QVERIFY(writeFileAtomically(path("old.png"), "an earlier export's").ok());
    QVERIFY(!removeOwned(path("hard.png")).ok()); // an input
    QVERIFY(!removeOwned(path("pipe.png")).ok()); // not a file we wrote
    QVERIFY(!removeOwned(path("link.png")).ok());
    QVERIFY(removeOwned(path("old.png")).ok());
    QVERIFY(!fs::exists(path("old.png")));
    // A folder is never removed as a file; a stage of this run's, discarded, loses only names:
    // an input linked into it keeps its data and its own name.
    fs::create_directory(path("stage"));
    fs::create_hard_link(path("h.png"), path("stage/h.png"));
    QVERIFY(writeFileAtomically(path("stage/new.png"), "new").ok());
    QVERIFY(!removeOwned(path("stage")).ok());
    discardTemporary(path("stage"));
    QVERIFY(!fs::exists(path("stage")));
    QCOMPARE(readTextFile(path("h.png"), false).value(), std::string("height"));
}

// The editor saves, exports and bakes on worker threads at once: each run sees only its own
// inputs. A run on one thread refuses its input; another thread's run may write that file; a
// session opened inside a run joins it.
void OutputGateTest::eachThreadsRunHasItsOwnInputs() {
    const InputSession save;
    QVERIFY(InputFile::open(path("h.png")).ok());
    QVERIFY(!checkReplaceable(path("h.png")).ok());
    {
        const InputSession nested; // joins the thread's run
        QVERIFY(!checkReplaceable(path("hard.png")).ok());
    }
    QVERIFY(!checkReplaceable(path("h.png")).ok()); // still recorded: the nested one only joined
    bool otherRunRefused = true, otherRunSeesItsOwn = false;
    std::thread exportJob([&] {
        const InputSession run;
        otherRunRefused = !checkReplaceable(path("h.png")).ok();
        otherRunSeesItsOwn =
            InputFile::open(path("hard.png")).ok() && !checkReplaceable(path("h.png")).ok();
    });
    exportJob.join();
    QVERIFY(!otherRunRefused);
    QVERIFY(otherRunSeesItsOwn);
    QVERIFY(!checkReplaceable(path("h.png")).ok());
}

QTEST_GUILESS_MAIN(OutputGateTest)
#include "OutputGateTest.moc"

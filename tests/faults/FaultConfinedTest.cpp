// Outputs confined by construction: nothing a run finds on disk is obeyed (planted stages,
// journals, links of every shape, with an archive's old timestamps), a link swapped in while a
// leftover is removed redirects nothing, any legal name (200-255 bytes, not UTF-8) is written,
// standard output closed or full is an error, a mount point is an ordinary target, and a
// command's several files are all or nothing. Every case hashes a sibling "victim" folder and a
// fake $HOME before and after: nothing outside the output's folder may change.

#include "FaultSupport.h"
#include "parallax/io/Temporaries.h"

#include <QProcess>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <atomic>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using namespace px::faults;
namespace fs = std::filesystem;

namespace {

// A process's output when run through the shell (bytes a QString cannot carry, redirections).
CliRun runShell(const QString& folder, const QString& script, const QStringList& environment = {}) {
    QProcess process;
    process.setWorkingDirectory(folder);
    process.setProcessChannelMode(QProcess::MergedChannels);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("CLI", QStringLiteral(PX_CLI_PATH));
    for (const QString& entry : environment)
        env.insert(entry.section('=', 0, 0), entry.section('=', 1));
    process.setProcessEnvironment(env);
    process.start("/bin/sh", {"-c", script});
    process.waitForFinished(300000);
    CliRun run;
    run.output = QString::fromUtf8(process.readAll());
    if (process.exitStatus() == QProcess::CrashExit)
        run.signal = -1;
    else
        run.status = process.exitCode();
    return run;
}

// Sets every entry under `path` (links themselves too) to 1980, as an old archive extracts them.
void makeOld(const fs::path& path) {
    const timespec times[2] = {{315532800, 0}, {315532800, 0}};
    std::error_code ec;
    if (fs::is_directory(fs::symlink_status(path, ec))) {
        for (const fs::directory_entry& e : fs::directory_iterator(path, ec))
            makeOld(e.path());
    }
    ::utimensat(AT_FDCWD, path.c_str(), times, AT_SYMLINK_NOFOLLOW);
}

// Hidden entries of `folder` that were not there before (names only; a stage's files are inside).
QStringList newHidden(const QString& folder, const QStringList& before = {}) {
    QStringList found;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(folder.toStdString(), ec)) {
        const QString name = QString::fromStdString(e.path().filename().string());
        if (name.startsWith('.') && name != ".parallax-export" && !before.contains(name))
            found << name;
    }
    return found;
}

} // namespace

class FaultConfinedTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { printTally("confined"); }
    void plantedLeftoversNeverObeyed_data();
    void plantedLeftoversNeverObeyed();
    void swapRacingTheRemoval();
    void longNames_data();
    void longNames();
    void nonUtf8Names_data();
    void nonUtf8Names();
    void standardOutputLost_data();
    void standardOutputLost();
    void mountPointTarget();
    void sideFilesAllOrNothing_data();
    void sideFilesAllOrNothing();

private:
    // A fresh case: ROOT/work (a copy of the template), ROOT/victim, ROOT/home. Returns work.
    QString prepare(const QString& name);
    void expectOutsideUnchanged(const QString& root, const QMap<QString, QByteArray>& victim,
                                const QMap<QString, QByteArray>& home);
    QTemporaryDir m_temp;
    QString m_template;
    quint32 m_seed = 0;
};

void FaultConfinedTest::initTestCase() {
    QVERIFY(m_temp.isValid());
    m_seed = QRandomGenerator::global()->generate();
    qInfo("seed %u (the victim's bytes and the planted shapes' contents)", m_seed);
    m_template = m_temp.path() + "/template";
    QDir().mkpath(m_template + "/set");
    QVERIFY(writeSample(m_template + "/h.png", "noise", 32));
    QCOMPARE(
        runCli(m_template, {"export", "--height", "h.png", "--format", "gltf", "--out", "earlier"})
            .status,
        0);
    const CliRun normal = runCli(
        m_template, {"bake", "normal", "--height", "h.png", "--out", "set/stone_normal.png"});
    QVERIFY2(normal.status == 0, qPrintable(normal.output));
}

QString FaultConfinedTest::prepare(const QString& name) {
    const QString root = m_temp.path() + "/" + name;
    QDir(root).removeRecursively();
    QDir().mkpath(root);
    if (!copyFolder(m_template, root + "/work"))
        return {};
    QRandomGenerator random(m_seed);
    QDir().mkpath(root + "/victim/sub");
    for (int i = 0; i < 40; ++i) {
        QByteArray bytes(64 + static_cast<int>(random.bounded(512)), '\0');
        for (char& c : bytes)
            c = static_cast<char>(random.bounded(256));
        writeFile(root + (i % 4 == 0 ? "/victim/sub/f" : "/victim/f") + QString::number(i), bytes);
    }
    QDir().mkpath(root + "/home");
    writeFile(root + "/home/.bashrc", "# the user's own\n");
    writeFile(root + "/home/notes.txt", "keep me\n");
    return root + "/work";
}

void FaultConfinedTest::expectOutsideUnchanged(const QString& root,
                                               const QMap<QString, QByteArray>& victim,
                                               const QMap<QString, QByteArray>& home) {
    const QString v = difference(victim, snapshot(root + "/victim"));
    QVERIFY2(v.isEmpty(), qPrintable("the victim folder changed: " + v));
    const QString h = difference(home, snapshot(root + "/home"));
    QVERIFY2(h.isEmpty(), qPrintable("$HOME changed: " + h));
}

void FaultConfinedTest::plantedLeftoversNeverObeyed_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("where"); // the folder the writer sweeps, under work
    QTest::addColumn<QString>("key");   // the name the leftovers are named after
    QTest::addColumn<QString>("shape");
    const QList<std::tuple<QString, QStringList, QString, QString>> commands = {
        {"sample", {"sample", "bricks", "--size", "16", "--out", "out.png"}, ".", "out.png"},
        {"bake", {"bake", "normal", "--height", "h.png", "--out", "n.png"}, ".", "n.png"},
        {"export", {"export", "--height", "h.png", "--format", "gltf", "--out", "pkg"}, ".", "pkg"},
        {"export --force",
         {"export", "--height", "h.png", "--format", "gltf", "--out", "earlier", "--force"},
         "earlier",
         "earlier"},
        {"render --turntable",
         {"render", "--height", "h.png", "--turntable", "2", "--size", "16", "--out", "spin.png"},
         ".",
         "spin-000.png"},
    };
    // Shapes a writer makes (removed, or left, but never obeyed) and shapes it never makes (left
    // alone and named): each command meets three of the seven, turn by turn (PX_FAULTS_ALL=1:
    // all).
    const QStringList shapes = {
        "old journal",         "journal into home",      "stage with a link",
        "stage with a folder", "stage with a hard link", "temporary that is a link",
        "stage that is a link"};
    int c = 0;
    for (const auto& [name, args, where, key] : commands) {
        for (int s = 0; s < shapes.size(); ++s) {
            if (takesCase(c, s, static_cast<int>(shapes.size()), 3))
                QTest::newRow(qPrintable(name + ", " + shapes[s]))
                    << args << where << key << shapes[s];
        }
        ++c;
    }
}

// A leftover planted beside (or in) the target, as an archive would carry it: the command does
// its work, nothing outside its folder changes, and what is not provably a dead writer's is left
// where it was and named in a note.
void FaultConfinedTest::plantedLeftoversNeverObeyed() {
    QFETCH(QStringList, args);
    QFETCH(QString, where);
    QFETCH(QString, key);
    QFETCH(QString, shape);
    const QString work = prepare("planted");
    QVERIFY(!work.isEmpty());
    const QString root = QFileInfo(work).path();
    const QString dir = work + "/" + where;
    const fs::path at = dir.toStdString();
    const std::string k = key.toStdString();
    std::string planted;
    bool ours = false; // a shape a dead writer leaves: it may go
    if (shape == "old journal") {
        planted = "." + k + ".export-tmp4242-0.0badf00d";
        fs::create_directory(at / planted);
        struct stat st {};
        QCOMPARE(::stat((root + "/victim/f1").toLocal8Bit().constData(), &st), 0);
        writeFile(QString::fromStdString((at / planted / ".parallax-commit").string()),
                  "parallax-commit 1\ninto ../../victim\nmove f2\nremove " +
                      QByteArray::number(static_cast<qulonglong>(st.st_dev)) + " " +
                      QByteArray::number(static_cast<qulonglong>(st.st_ino)) + " f1\n");
        writeFile(QString::fromStdString((at / planted / "f2").string()), "planted");
    } else if (shape == "journal into home") {
        planted = px::temporaryName(k, "stage");
        fs::create_directory(at / planted);
        writeFile(QString::fromStdString((at / planted / ".parallax-commit").string()),
                  "parallax-commit 1\ninto ../../home\nmove .bashrc\n");
        writeFile(QString::fromStdString((at / planted / ".bashrc").string()), "rm -rf ~\n");
        ours = true;
    } else if (shape == "stage with a link" || shape == "stage with a folder" ||
               shape == "stage with a hard link") {
        planted = px::temporaryName(k, "stage");
        fs::create_directory(at / planted);
        writeFile(QString::fromStdString((at / planted / "a.png").string()), "planted");
        const fs::path victim = (root + "/victim").toStdString();
        if (shape.endsWith("a link"))
            fs::create_directory_symlink(victim, at / planted / "v");
        else if (shape.endsWith("folder"))
            fs::create_directory(at / planted / "sub");
        else
            fs::create_hard_link(victim / "f3", at / planted / "f3");
    } else if (shape == "temporary that is a link") {
        planted = px::temporaryName(k, "tmp");
        fs::create_symlink((root + "/victim/f5").toStdString(), at / planted);
    } else {
        planted = px::temporaryName(k, "stage");
        fs::create_directory_symlink((root + "/victim").toStdString(), at / planted);
    }
    makeOld(at / planted);
    const auto victim = snapshot(root + "/victim");
    const auto home = snapshot(root + "/home");
    const CliRun run = runCli(work, args, {"HOME=" + root + "/home"});
    QVERIFY2(run.status == 0, qPrintable(run.output));
    expectOutsideUnchanged(root, victim, home);
    const bool left = fs::exists(fs::symlink_status(at / planted));
    if (!ours) {
        QVERIFY2(left, planted.c_str());
        if (shape != "old journal") // not our name at all: not even looked at
            QVERIFY2(run.output.contains(QRegularExpression(
                         "note: " + QRegularExpression::escape(QString::fromStdString(planted)) +
                         ": left alone, not provably a dead run's leftover \\(")),
                     qPrintable(run.output));
    }
    record(run, true, false, 0);
}

// A dead-looking stage whose entry x a thread exchanges, as fast as it can, with a link to the
// victim folder kept outside (renameat2 RENAME_EXCHANGE) while a run sweeps it: whatever instant
// each check and removal meet, nothing of the victim may go. Bounded iterations, no sleeps.
void FaultConfinedTest::swapRacingTheRemoval() {
    const QString work = prepare("swap");
    QVERIFY(!work.isEmpty());
    const QString root = QFileInfo(work).path();
    const auto victim = snapshot(root + "/victim");
    const auto home = snapshot(root + "/home");
    QDir().mkpath(root + "/holder");
    const int holder = ::open((root + "/holder").toLocal8Bit().constData(), O_RDONLY | O_DIRECTORY);
    QVERIFY(holder >= 0);
    int removedOrKept[2] = {0, 0};
    for (int round = 0; round < 6; ++round) {
        const fs::path stage = fs::path(work.toStdString()) / px::temporaryName("out.png", "stage");
        fs::create_directory(stage);
        for (int i = 0; i < 50 + 40 * round; ++i)
            writeFile(QString::fromStdString((stage / ("f" + std::to_string(i))).string()), "x");
        writeFile(QString::fromStdString((stage / "x").string()), "file");
        std::error_code ec;
        fs::remove(fs::path((root + "/holder/x").toStdString()), ec);
        fs::create_directory_symlink((root + "/victim").toStdString(),
                                     (root + "/holder/x").toStdString());
        const int fd = ::open(stage.c_str(), O_RDONLY | O_DIRECTORY);
        QVERIFY(fd >= 0);
        std::atomic<bool> stop{false};
        std::thread swapper([&] {
            for (long i = 0; i < 20000000 && !stop.load(); ++i) {
                if (::renameat2(fd, "x", holder, "x", RENAME_EXCHANGE) != 0)
                    break; // removed by the sweep
            }
        });
        const CliRun run = runCli(work, {"sample", "bricks", "--size", "16", "--seed",
                                         QString::number(round + 1), "--out", "out.png"});
        stop.store(true);
        swapper.join();
        ::close(fd);
        QVERIFY2(run.status == 0, qPrintable(run.output));
        expectOutsideUnchanged(root, victim, home);
        ++removedOrKept[fs::exists(stage) ? 1 : 0];
        fs::remove_all(stage, ec); // the test's own cleanup (remove_all does not follow links)
        record(run, true, false, 0);
    }
    ::close(holder);
    qInfo("swap race: %d stages removed, %d left alone", removedOrKept[0], removedOrKept[1]);
}

void FaultConfinedTest::longNames_data() {
    QTest::addColumn<int>("bytes");
    for (int n : {200, 231, 250, 255})
        QTest::newRow(qPrintable(QString::number(n) + " bytes")) << n;
}

// Every legal name is an output: a file replaced, an export folder written then updated, a
// turntable's frames; nothing hidden is left.
void FaultConfinedTest::longNames() {
    QFETCH(int, bytes);
    const QString work = prepare("long");
    QVERIFY(!work.isEmpty());
    const QStringList before = newHidden(work);
    const QString file = QString(bytes - 4, QChar('f')) + ".png";
    const QString folder = QString(bytes, QChar('e'));
    const QString frames = QString(bytes - 8, QChar('t')) + ".png"; // + "-000"
    const QList<QStringList> runs = {
        {"sample", "bricks", "--size", "16", "--out", file},
        {"sample", "bricks", "--size", "16", "--seed", "2", "--out", file},
        {"export", "--height", "h.png", "--format", "godot", "--out", folder},
        {"export", "--height", "h.png", "--format", "godot", "--out", folder, "--force"},
        {"render", "--height", "h.png", "--turntable", "2", "--size", "16", "--out", frames},
    };
    for (const QStringList& args : runs) {
        const CliRun run = runCli(work, args);
        QVERIFY2(run.status == 0, qPrintable(args.join(' ') + ":\n" + run.output));
        QCOMPARE(newHidden(work, before), QStringList());
        record(run, true, false, 0);
    }
    QVERIFY(QFileInfo(work + "/" + file).isFile());
    QVERIFY(QFileInfo(work + "/" + folder + "/.parallax-export").isFile());
    QCOMPARE(newHidden(work + "/" + folder), QStringList());
}

void FaultConfinedTest::nonUtf8Names_data() {
    QTest::addColumn<QString>("format");
    for (const char* format : {"package", "gltf", "godot", "unreal", "unity"})
        QTest::newRow(format) << format;
}

// A height map named in Latin-1 (an old zip archive's names) exports in every format: exit 0,
// the files written, nothing hidden left.
void FaultConfinedTest::nonUtf8Names() {
    QFETCH(QString, format);
    const QString work = prepare("latin1");
    QVERIFY(!work.isEmpty());
    fs::copy_file(fs::path(work.toStdString()) / "h.png",
                  fs::path(work.toStdString()) / "pierre-\xe9t\xe9.png");
    const CliRun run = runShell(
        work, "exec \"$CLI\" export --height \"$(printf 'pierre-\\351t\\351.png')\" --format " +
                  format + " --out out");
    QVERIFY2(run.status == 0, qPrintable(run.output));
    QVERIFY(QFileInfo(work + "/out/.parallax-export").isFile());
    QCOMPARE(newHidden(work), QStringList());
    QCOMPARE(newHidden(work + "/out"), QStringList());
    record(run, true, false, 0);
    std::error_code ec;
    fs::remove_all(work.toStdString(), ec); // names Qt cannot spell, so QTemporaryDir cannot remove
}

void FaultConfinedTest::standardOutputLost_data() {
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("redirect");
    QTest::addColumn<QString>("reason");
    const QStringList commands = {
        "trace --height h.png --rays 8 --out -",
        QString("bench --height h.png --rays 4 --polar 60 --techniques pom --defaults-only ") +
            "--repeats 0 --quiet --out -",
        "shader --technique pom --out -",
        "shader --list",
        "recommend --height h.png --max-polar 60 --techniques cone --cache off",
        "recommend --height h.png --max-polar 60 --techniques cone --cache off --json",
    };
    const QList<std::pair<QString, QString>> ways = {
        {">/dev/full", "writing failed \\(No space left on device\\)"}, {">&-", "it is closed"}};
    for (int c = 0; c < commands.size(); ++c) {
        for (int w = 0; w < ways.size(); ++w) {
            if (takesCase(c, w, 2, 1) || c < 2)
                QTest::newRow(qPrintable(commands[c].section(' ', 0, 1) + " " + ways[w].first))
                    << commands[c] << ways[w].first << ways[w].second;
        }
    }
}

// Standard output is an output: full or closed, the command says so and exits 1.
void FaultConfinedTest::standardOutputLost() {
    QFETCH(QString, command);
    QFETCH(QString, redirect);
    QFETCH(QString, reason);
    const QString work = prepare("stdout");
    QVERIFY(!work.isEmpty());
    const auto before = snapshot(work);
    const CliRun run = runShell(work, "exec \"$CLI\" " + command + " " + redirect);
    QVERIFY2(run.status == 1, qPrintable(QString::number(run.status) + ":\n" + run.output));
    QVERIFY2(run.output.contains(QRegularExpression("error: standard output: " + reason +
                                                    "; what the command wrote there is lost")),
             qPrintable(run.output));
    QCOMPARE(difference(before, snapshot(work)), QString());
    record(run, true, false, 0);
}

// A target folder that is a mount point (a container's volume): an export into it, then an
// update, then a shader dump that fills it. Stages are made on its device; nothing is left
// beside it or in it; the dump that does not fit changes nothing.
void FaultConfinedTest::mountPointTarget() {
    const QString work = prepare("mount");
    QVERIFY(!work.isEmpty());
    QString why;
    if (!mountTmpfs(work + "/vol", 96, why))
        QSKIP(qPrintable("cannot mount a tmpfs here (" + why + "): run as root"));
    const auto unmountAtEnd = qScopeGuard([&] { unmount(work + "/vol"); });
    const QStringList before = newHidden(work);
    for (const QStringList& args :
         {QStringList{"export", "--height", "h.png", "--format", "gltf", "--out", "vol"},
          QStringList{"export", "--height", "h.png", "--format", "gltf", "--invert", "--out", "vol",
                      "--force"}}) {
        const CliRun run = runCli(work, args);
        QVERIFY2(run.status == 0, qPrintable(run.output));
        QCOMPARE(newHidden(work, before), QStringList());
        QCOMPARE(newHidden(work + "/vol"), QStringList());
        record(run, true, false, 0);
    }
    QVERIFY(QFileInfo(work + "/vol/h.gltf").isFile());
    PX_EXPECT_CLEAN_FAILURE(work, QStringList({"shader", "--dump-all", "vol/shaders"}), {}, 1,
                            "vol/shaders", "No space left on device");
}

void FaultConfinedTest::sideFilesAllOrNothing_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("env");
    QTest::addColumn<int>("status");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("reason");
    const QStringList bench = {"bench",     "--height", "h.png",        "--rays", "4",
                               "--polar",   "60",       "--techniques", "pom",    "--defaults-only",
                               "--repeats", "0",        "--quiet",      "--out",  "a.csv",
                               "--plot",    "p.svg"};
    QTest::newRow("bench: the plot does not fit")
        << bench << "PX_TEST_FAIL_WRITE_AT=4096" << 1 << "p.svg"
        << "No space left on device";
    QTest::newRow("bench: Ctrl-C at the plot")
        << bench << "PX_TEST_RAISE=INT:write@2" << 130 << "error:"
        << "interrupted \\(SIGINT\\)";
    const QStringList import = {"import", "set", "--out", "m.json", "--derive-height", "--force"};
    QTest::newRow("import --derive-height: the height map does not fit")
        << import << "PX_TEST_FAIL_WRITE_AT=300" << 1 << "m"
        << "No space left on device";
    QTest::newRow("import --derive-height: Ctrl-C at the material")
        << import << "PX_TEST_RAISE=INT:write@2" << 130 << "error:"
        << "interrupted \\(SIGINT\\)";
    for (const char* at : {"1", "40", "150"}) {
        QTest::newRow(qPrintable(QString("shader --dump-all: Ctrl-C at file ") + at))
            << QStringList{"shader", "--dump-all", "dump"}
            << QString("PX_TEST_RAISE=INT:write@") + at << 130 << "error:"
            << "interrupted \\(SIGINT\\)";
    }
    QTest::newRow("shader --dump-all, a new folder: SIGTERM at file 80")
        << QStringList{"shader", "--dump-all", "fresh-dump"} << "PX_TEST_RAISE=TERM:write@80" << 130
        << "error:"
        << "terminated \\(SIGTERM\\)";
}

// A command's files are one output: a failure or an interruption at any of them leaves every
// earlier file byte-identical and nothing behind.
void FaultConfinedTest::sideFilesAllOrNothing() {
    QFETCH(QStringList, args);
    QFETCH(QString, env);
    QFETCH(int, status);
    QFETCH(QString, file);
    QFETCH(QString, reason);
    const QString work = prepare("side");
    QVERIFY(!work.isEmpty());
    if (args.contains("--dump-all")) {
        // Seven thousand variants are not dumped whole here (one fsync each): a folder of the
        // user's files, or none (a new folder must not appear), and the run stopped early on.
        if (args.last() == "dump") {
            QDir().mkpath(work + "/dump");
            writeFile(work + "/dump/mine.txt", "the user's own file among the shaders\n");
            writeFile(work + "/dump/old.frag", "// an earlier dump's\n");
        }
    } else {
        // The previous outputs: a run without a fault, each file then made different from what
        // the next run writes, so that a replaced one shows.
        const auto start = snapshot(work);
        const CliRun first = runCli(work, args);
        QVERIFY2(first.status == 0, qPrintable(first.output));
        const auto written = snapshot(work);
        for (auto it = written.begin(); it != written.end(); ++it) {
            if (!start.contains(it.key()) && !it.key().endsWith('/'))
                writeFile(work + "/" + it.key(), "the previous " + it.key().toUtf8() + "\n");
        }
    }
    PX_EXPECT_CLEAN_FAILURE(work, args, {env}, status, file, reason);
}

PX_FAULTS_MAIN(FaultConfinedTest)
#include "FaultConfinedTest.moc"

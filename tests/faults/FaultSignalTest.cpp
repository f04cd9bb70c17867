// Ctrl-C, SIGTERM and SIGKILL at several moments of every kind of write: the command stops at
// once, removes its temporary files and folders, leaves the previous output as it was and exits
// 130; what a SIGKILL leaves behind is removed by the next run on the same target. The moments
// are exact (PX_TEST_RAISE=SIGNAL:POINT raises the signal in the process at that point), and one
// case sends SIGINT from outside during a long bake and measures how soon the process is gone.

#include "FaultSupport.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <csignal>
#include <sys/wait.h>

using namespace px::faults;

class FaultSignalTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { printTally("signals"); }
    void interruptAtAMoment_data();
    void interruptAtAMoment();
    void interruptDuringAnUpdateFinishesIt();
    void killedRunsDebrisRemovedByTheNext_data();
    void killedRunsDebrisRemovedByTheNext();
    void ctrlCFromOutsideStopsAtOnce();
    void interruptDuringTheFramesFinishesThem_data();
    void interruptDuringTheFramesFinishesThem();
    void secondWriterRefused_data();
    void secondWriterRefused();

private:
    void prepare(const QString& folder);
    const QMap<QString, QByteArray>* cleanRun(const QStringList& args);
    QTemporaryDir m_temp;
    QString m_template;
    QMap<QString, QMap<QString, QByteArray>> m_clean; // by the command's arguments
};

// The starting folder of every case: a height map, previous outputs and an earlier export with
// an engine's file beside it. Made once (one run of the CLI); each case starts from a copy.
void FaultSignalTest::initTestCase() {
    QVERIFY(m_temp.isValid());
    m_template = m_temp.path() + "/template";
    QDir().mkpath(m_template);
    QVERIFY(writeSample(m_template + "/h.png", "noise", 32));
    for (const char* previous :
         {"out.png", "out.csv", "spin-000.png", "spin-001.png", "spin-002.png"}) {
        QFile file(m_template + "/" + previous);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray("the previous ") + previous + "\n");
    }
    QCOMPARE(
        runCli(m_template, {"export", "--height", "h.png", "--format", "godot", "--out", "earlier"})
            .status,
        0);
    QFile meta(m_template + "/earlier/h.png.import"); // an engine's file beside the export
    QVERIFY(meta.open(QIODevice::WriteOnly));
    meta.write("uid://keep");
}

void FaultSignalTest::prepare(const QString& folder) {
    QVERIFY(copyFolder(m_template, folder));
}

// What an uninterrupted run of `args` leaves in a fresh starting folder: run once per command.
const QMap<QString, QByteArray>* FaultSignalTest::cleanRun(const QStringList& args) {
    const QString key = args.join('\n');
    if (!m_clean.contains(key)) {
        const QString folder = m_temp.path() + "/clean";
        if (!copyFolder(m_template, folder))
            return nullptr;
        const CliRun run = runCli(folder, args);
        if (run.status != 0) {
            qWarning("%s", qPrintable(run.output));
            return nullptr;
        }
        m_clean.insert(key, snapshot(folder));
    }
    return &m_clean[key];
}

void FaultSignalTest::interruptAtAMoment_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("signal");
    QTest::addColumn<QString>("point");
    const QList<QPair<QString, QStringList>> commands = {
        {"bake", {"bake", "relaxed-cone", "--height", "h.png", "--out", "out.png"}},
        {"sample", {"sample", "bricks", "--size", "64", "--out", "out.png"}},
        {"trace", {"trace", "--height", "h.png", "--rays", "8", "--out", "out.csv"}},
        {"export", {"export", "--height", "h.png", "--format", "unity", "--out", "fresh"}},
        {"export --force",
         {"export", "--height", "h.png", "--format", "godot", "--out", "earlier", "--force"}},
        {"render --turntable",
         {"render", "--height", "h.png", "--turntable", "3", "--size", "16", "--out", "spin.png"}},
    };
    // Every command at each of its moments, under one of SIGINT, SIGTERM and SIGHUP turn by turn:
    // one handler serves the three (only its message differs), and each signal meets every
    // command that has three moments and every moment but export-commit and frames-commit
    // (PX_FAULTS_ALL=1: all three signals at every moment).
    const QStringList raised = {"INT", "TERM", "HUP"};
    int c = 0;
    for (const auto& [name, args] : commands) {
        QStringList points = {"write", "commit"};
        if (name.startsWith("export"))
            points << "export-commit";
        if (name.startsWith("render"))
            points << "frames-commit";
        for (int p = 0; p < points.size(); ++p) {
            for (int s = 0; s < raised.size(); ++s) {
                if (takesCase(c + p, s, static_cast<int>(raised.size()), 1))
                    QTest::newRow(qPrintable(name + " SIG" + raised[s] + " at " + points[p]))
                        << args << raised[s] << points[p];
            }
        }
        ++c;
    }
}

void FaultSignalTest::interruptAtAMoment() {
    QFETCH(QStringList, args);
    QFETCH(QString, signal);
    QFETCH(QString, point);
    const QString folder = m_temp.path() + "/moment";
    prepare(folder);
    const QString said = signal == "INT"   ? "interrupted \\(SIGINT\\)"
                         : signal == "HUP" ? "hung up \\(SIGHUP\\)"
                                           : "terminated \\(SIGTERM\\)";
    PX_EXPECT_CLEAN_FAILURE(folder, args, {"PX_TEST_RAISE=" + signal + ":" + point}, 130,
                            "error:", said + ": stopped, temporary files removed");
}

// The few renames of an in-place update are not interrupted half-way: the signal waits for the
// last one, so the folder holds the whole new export (and the engine's files), never a mix.
void FaultSignalTest::interruptDuringAnUpdateFinishesIt() {
    const QString folder = m_temp.path() + "/update";
    prepare(folder);
    const QStringList args = {"export",   "--height", "h.png",   "--format", "godot",
                              "--invert", "--out",    "earlier", "--force"};
    const CliRun run = runCli(folder, args, {"PX_TEST_RAISE=INT:export-update"});
    QCOMPARE(run.status, 130);
    const auto after = snapshot(folder);
    QCOMPARE(after.value("earlier/h.png.import"), QByteArray("uid://keep"));
    // Byte for byte what the update writes uninterrupted, the engine's file kept, nothing more.
    const auto* reference = cleanRun(args);
    QVERIFY(reference != nullptr);
    QVERIFY(reference->value("earlier/h_normal.png") !=
            snapshot(m_template).value("earlier/h_normal.png"));
    QCOMPARE(difference(*reference, after), QString());
    for (const QString& name : after.keys())
        QVERIFY2(!name.startsWith("."), qPrintable("left behind: " + name));
    record(run, true, false, 0);
}

void FaultSignalTest::killedRunsDebrisRemovedByTheNext_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("point");
    QTest::addColumn<QString>("debris");
    QTest::newRow("sample") << QStringList{"sample", "bricks", "--size", "64", "--out", "out.png"}
                            << "write"
                            << "^\\.px-tmp-[0-9a-f]{16}-[0-9a-f]{16}$";
    QTest::newRow("export") << QStringList{"export", "--height", "h.png", "--format",
                                           "gltf",   "--out",    "fresh"}
                            << "export-commit"
                            << "^\\.px-stage-[0-9a-f]{16}-[0-9a-f]{16}/$";
    QTest::newRow("export --force, half updated")
        << QStringList{"export",   "--height", "h.png",   "--format", "godot",
                       "--invert", "--out",    "earlier", "--force"}
        << "export-update"
        << "^earlier/\\.px-stage-[0-9a-f]{16}-[0-9a-f]{16}/$";
    const QStringList spin = {"render", "--height", "h.png", "--turntable", "3",
                              "--size", "16",       "--out", "spin.png"};
    QTest::newRow("render --turntable, a frame half written")
        << spin << "write"
        << "^\\.px-stage-[0-9a-f]{16}-[0-9a-f]{16}/$";
    QTest::newRow("render --turntable, every frame staged")
        << spin << "frames-commit"
        << "^\\.px-stage-[0-9a-f]{16}-[0-9a-f]{16}/$";
    QTest::newRow("render --turntable, half the frames moved")
        << spin << "frames-update"
        << "^\\.px-stage-[0-9a-f]{16}-[0-9a-f]{16}/$";
}

void FaultSignalTest::killedRunsDebrisRemovedByTheNext() {
    QFETCH(QStringList, args);
    QFETCH(QString, point);
    QFETCH(QString, debris);
    const QString folder = m_temp.path() + "/killed";
    prepare(folder);
    const auto before = snapshot(folder);
    const CliRun killed = runCli(folder, args, {"PX_TEST_RAISE=KILL:" + point});
    QVERIFY2(killed.signal != 0, qPrintable(killed.output)); // SIGKILL: nothing can clean up
    QStringList left;
    for (const QString& name : snapshot(folder).keys()) {
        if (!before.contains(name))
            left << name;
    }
    QVERIFY2(!left.filter(QRegularExpression(debris)).isEmpty(), qPrintable(left.join(' ')));
    // Before a commit is decided the previous output is whole; after (half the moves done), the
    // journal in the stage lets the next run finish it.
    if (!point.endsWith("-update")) {
        for (const QString& name : before.keys())
            QCOMPARE(snapshot(folder).value(name), before.value(name));
    }

    const CliRun next = runCli(folder, args);
    QVERIFY2(next.status == 0, qPrintable(next.output));
    // Nothing hidden is left but what was there before: no stage, no temporary, no lock.
    for (const QString& name : snapshot(folder).keys()) {
        const QString base = name.section('/', -1, -1).isEmpty() ? name.section('/', -2, -2)
                                                                 : name.section('/', -1, -1);
        QVERIFY2(!base.startsWith('.') || before.contains(name) || base == ".parallax-export",
                 qPrintable("left behind: " + name));
    }
    // And the output is what a clean run writes.
    const auto* reference = cleanRun(args);
    QVERIFY(reference != nullptr);
    const auto result = snapshot(folder);
    for (auto it = reference->begin(); it != reference->end(); ++it) {
        if (!it.key().endsWith(".parallax-export") && !it.key().endsWith("h.png"))
            QVERIFY2(result.value(it.key()) == it.value(), qPrintable("differs: " + it.key()));
    }
    record(next, true, false, 0);
}

void FaultSignalTest::ctrlCFromOutsideStopsAtOnce() {
    const QString folder = m_temp.path() + "/outside";
    prepare(folder);
    QVERIFY(writeSample(folder + "/big.png", "noise", 1024));
    const auto before = snapshot(folder);
    QProcess process;
    process.setWorkingDirectory(folder);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(QStringLiteral(PX_CLI_PATH),
                  {"bake", "relaxed-cone", "--height", "big.png", "--out", "out.png"});
    // The progress line appears once the bake has run for a second: then it is mid-bake.
    QByteArray output;
    while (!output.contains("baking relaxed-cone map:") && process.waitForReadyRead(60000))
        output += process.readAll();
    QVERIFY2(output.contains("baking relaxed-cone map:"), output.constData());
    ::kill(static_cast<pid_t>(process.processId()), SIGINT);
    QVERIFY(process.waitForFinished(60000)); // a hang guard only
    output += process.readAll();
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QCOMPARE(process.exitCode(), 130);
    QCOMPARE(difference(before, snapshot(folder)), QString());
    // Acted on at once, whatever the machine's speed: the handler's sentence is the last thing
    // the process wrote (it exits as it writes it), and the bake never got to its end.
    const QByteArray said = "error: interrupted (SIGINT): stopped, temporary files removed\n";
    QVERIFY2(output.endsWith(said), output.constData());
    QVERIFY2(!output.contains("100%") && !output.contains("wrote"), output.constData());
    CliRun run;
    run.status = 130;
    record(run, true, false, 0);
}

void FaultSignalTest::interruptDuringTheFramesFinishesThem_data() {
    QTest::addColumn<QString>("signal");
    QTest::addColumn<QString>("said");
    QTest::newRow("SIGINT") << "INT"
                            << "interrupted \\(SIGINT\\)";
    QTest::newRow("SIGTERM") << "TERM"
                             << "terminated \\(SIGTERM\\)";
}

// Ctrl-C or SIGTERM while the frames move into place waits for the last one: the folder holds the
// whole new set, exactly what an uninterrupted run writes, and nothing hidden.
void FaultSignalTest::interruptDuringTheFramesFinishesThem() {
    QFETCH(QString, signal);
    QFETCH(QString, said);
    const QString folder = m_temp.path() + "/frames";
    prepare(folder);
    const QStringList args = {"render", "--height", "h.png", "--turntable", "3",
                              "--size", "16",       "--out", "spin.png"};
    const CliRun run = runCli(folder, args, {"PX_TEST_RAISE=" + signal + ":frames-update"});
    QVERIFY2(run.status == 130, qPrintable(run.output));
    QVERIFY2(run.output.contains(QRegularExpression(said + ": stopped, temporary files removed")),
             qPrintable(run.output));
    const auto* reference = cleanRun(args);
    QVERIFY(reference != nullptr);
    const auto after = snapshot(folder);
    for (const char* frame : {"spin-000.png", "spin-001.png", "spin-002.png"})
        QVERIFY2(after.value(frame) == reference->value(frame), frame);
    for (const QString& name : after.keys())
        QVERIFY2(!name.startsWith('.'), qPrintable("left behind: " + name));
    record(run, true, false, 0);
}

void FaultSignalTest::secondWriterRefused_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("point");
    QTest::addColumn<QString>("target");
    QTest::newRow("export --force")
        << QStringList{"export",   "--height", "h.png",   "--format", "godot",
                       "--invert", "--out",    "earlier", "--force"}
        << "export-commit"
        << "earlier";
    QTest::newRow("render --turntable")
        << QStringList{"render", "--height", "h.png", "--turntable", "3",
                       "--size", "16",       "--out", "spin.png"}
        << "frames-commit"
        << "spin-000.png";
}

// Two writers of one export folder (or one set of frames) at once: the second is refused at
// once, naming the first, and changes nothing; the first then finishes. The first is stopped
// (SIGSTOP, by the test hook) with everything staged, so the two overlap for certain.
void FaultSignalTest::secondWriterRefused() {
    QFETCH(QStringList, args);
    QFETCH(QString, point);
    QFETCH(QString, target);
    const QString folder = m_temp.path() + "/two";
    prepare(folder);
    QProcess first;
    first.setWorkingDirectory(folder);
    first.setProcessChannelMode(QProcess::MergedChannels);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("PX_TEST_RAISE", "STOP:" + point);
    first.setProcessEnvironment(env);
    first.start(QStringLiteral(PX_CLI_PATH), args);
    QVERIFY(first.waitForStarted());
    const auto pid = static_cast<pid_t>(first.processId());
    siginfo_t info{};
    QVERIFY(::waitid(P_PID, static_cast<id_t>(pid), &info, WSTOPPED | WNOWAIT) == 0);
    QCOMPARE(info.si_code, CLD_STOPPED);
    PX_EXPECT_CLEAN_FAILURE(folder, args, {}, 1, target,
                            "another run \\(process " + QString::number(pid) +
                                "\\) is writing it now; nothing was changed");
    ::kill(pid, SIGCONT);
    QVERIFY(first.waitForFinished(120000));
    QCOMPARE(first.exitStatus(), QProcess::NormalExit);
    QVERIFY2(first.exitCode() == 0, first.readAll().constData());
    for (const QString& name : snapshot(folder).keys())
        QVERIFY2(!name.section('/', -1).startsWith(".") || name.endsWith(".parallax-export"),
                 qPrintable("left behind: " + name));
}

QTEST_GUILESS_MAIN(FaultSignalTest)
#include "FaultSignalTest.moc"

#pragma once
// The fault suite's tools: run parallax-cli as a user would (its own process, signals and all),
// photograph a folder byte for byte before and after, and count what every case showed.

#include <QByteArray>
#include <QMap>
#include <QObject>
#include <QString>
#include <QStringList>

namespace px::faults {

struct CliRun {
    int status = -1;      // exit status; -1 if killed by a signal
    int signal = 0;       // the signal that ended it, if any
    QString output;       // stdout and stderr together
    double seconds = 0.0; // wall time of the process
};

// Runs parallax-cli in `folder` with `environment` ("NAME=value") added; `addressSpace` > 0
// limits the process's memory (RLIMIT_AS, bytes): an allocation past it fails.
CliRun runCli(const QString& folder, const QStringList& arguments,
              const QStringList& environment = {}, long long addressSpace = 0);

// Writes `bytes` to `path` (a test's input file), replacing it.
void writeFile(const QString& path, const QByteArray& bytes);

// Writes the procedural map `name` to `path` byte for byte as `parallax-cli sample NAME --size SIZE
// --seed SEED --bits BITS --out PATH` does (the same core calls, without a process): an input
// that a case needs but does not test. False, with a warning, on failure.
bool writeSample(const QString& path, const QString& name, int size, unsigned seed = 1,
                 int bits = 16);

// Whether case (a, b) of a product A x B runs, where B's values (a signal, a byte, a kind of
// special file) are told apart in one function whatever A is (which command reaches it): each a
// takes `per` of B's `count` values, turn by turn from its own index, so every value of A and of B
// is still tried, several times over. PX_FAULTS_ALL=1 runs the whole product.
bool takesCase(int a, int b, int count, int per);

// Replaces `to` with a copy of the folder `from` (files and folders; every file a new inode):
// a case's starting folder copied from a template made once, instead of running the CLI again
// for every case (each run costs half a second of start-up). False, with a warning, on failure.
bool copyFolder(const QString& from, const QString& to);

// Every file and folder under `folder` (hidden ones included), with the bytes of each file (a
// symbolic link: its target; a FIFO, socket or device: its kind).
QMap<QString, QByteArray> snapshot(const QString& folder);

// Names what differs between two snapshots ("" if nothing): changed, added and removed entries.
QString difference(const QMap<QString, QByteArray>& before, const QMap<QString, QByteArray>& after);

// The suite's tally, printed at the end of each test program and summed in the docs.
struct Tally {
    int cases = 0, clearErrors = 0, crashes = 0;
    long long bytesLost = 0;
};
Tally& tally();
// Records one case: a clear error is a non-zero status with a message naming `file` and matching
// `reason`; a crash is death by a signal the run did not ask for; bytes lost are the bytes of
// files that changed or vanished.
void record(const CliRun& run, bool clearError, bool crashed, long long bytesLost);
long long bytesLost(const QMap<QString, QByteArray>& before,
                    const QMap<QString, QByteArray>& after);
void printTally(const char* suite);

// Tries to mount a tmpfs of `kilobytes` at `folder` (root in a container that allows it).
// Returns false, with the reason, where it cannot.
bool mountTmpfs(const QString& folder, int kilobytes, QString& why);
bool remountReadOnly(const QString& folder);
void unmount(const QString& folder);

// Runs the test object's functions as QTest::qExec does; under PX_TEST_SHARD=i/n (ctest's shards,
// px_shard_test) only every n-th of its test functions from the i-th, whole with their rows; of
// functions named on the command line, those the shard takes.
int execShard(QObject* test, int argc, char** argv);

} // namespace px::faults

// QTEST_GUILESS_MAIN, with the test's functions split between ctest's shards (execShard).
#define PX_FAULTS_MAIN(TestObject)                                                                 \
    int main(int argc, char** argv) {                                                              \
        QCoreApplication app(argc, argv);                                                          \
        TestObject test;                                                                           \
        QTEST_SET_MAIN_SOURCE_PATH                                                                 \
        return px::faults::execShard(&test, argc, argv);                                           \
    }

// Runs a case that must fail cleanly: status `rc`, the message naming `file` and matching
// `reason`, the folder byte-identical afterwards and nothing left behind.
#define PX_EXPECT_CLEAN_FAILURE(folder, args, env, rc, file, reason)                               \
    do {                                                                                           \
        QString said_;                                                                             \
        PX_EXPECT_CLEAN_FAILURE_SAYING(folder, args, env, rc, file, reason, said_);                \
    } while (false)

// The same, keeping what the run printed in `said` (a QString) for further checks.
#define PX_EXPECT_CLEAN_FAILURE_SAYING(folder, args, env, rc, file, reason, said)                  \
    do {                                                                                           \
        const auto before_ = px::faults::snapshot(folder);                                         \
        const px::faults::CliRun run_ = px::faults::runCli(folder, args, env);                     \
        const auto after_ = px::faults::snapshot(folder);                                          \
        (said) = run_.output;                                                                      \
        const bool named_ = run_.output.contains("error: ") && run_.output.contains(file) &&       \
                            !run_.output.contains(QRegularExpression("\\.px-(tmp|stage)-"));       \
        const bool reason_ = run_.output.contains(QRegularExpression(reason));                     \
        px::faults::record(run_, run_.status == (rc) && named_ && reason_, run_.signal != 0,       \
                           px::faults::bytesLost(before_, after_));                                \
        QVERIFY2(run_.signal == 0, qPrintable("killed by signal " + QString::number(run_.signal) + \
                                              ":\n" + run_.output));                               \
        QVERIFY2(run_.status == (rc),                                                              \
                 qPrintable("exit status " + QString::number(run_.status) + ":\n" + run_.output)); \
        QVERIFY2(named_, qPrintable("the message does not name " + QString(file) +                 \
                                    " (or names a temporary):\n" + run_.output));                  \
        QVERIFY2(reason_,                                                                          \
                 qPrintable("no reason matching " + QString(reason) + ":\n" + run_.output));       \
        const QString diff_ = px::faults::difference(before_, after_);                             \
        QVERIFY2(diff_.isEmpty(), qPrintable(diff_));                                              \
    } while (false)

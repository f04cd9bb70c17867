// A full disk and a read-only file system under every command that writes: the command fails
// naming its output and the reason, the previous output stays byte for byte, nothing is left.
// The full disk is a real 1 MB tmpfs where the test may mount one (root, as in CI containers
// that allow it) and, everywhere, the writer's injected failure at byte N (PX_TEST_FAIL_WRITE_AT).

#include "FaultSupport.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <unistd.h>

using namespace px::faults;

namespace {

// Each command that writes a file, writing `out` (its previous version is there already).
QList<QPair<QString, QStringList>> writers() {
    return {
        {"bake normal", {"bake", "normal", "--height", "h.png", "--out", "out.png"}},
        {"bake cone", {"bake", "cone", "--height", "h.png", "--out", "out.png"}},
        {"bake relaxed-cone", {"bake", "relaxed-cone", "--height", "h.png", "--out", "out.png"}},
        {"bake pyramid exr", {"bake", "pyramid", "--height", "h.png", "--out", "out.exr"}},
        {"sample png", {"sample", "bricks", "--size", "64", "--out", "out.png"}},
        {"sample tif", {"sample", "bricks", "--size", "64", "--out", "out.tif"}},
        {"trace csv", {"trace", "--height", "h.png", "--rays", "8", "--out", "out.csv"}},
        {"bench csv",
         {"bench", "--height", "h.png", "--rays", "4", "--polar", "60", "--techniques", "pom",
          "--defaults-only", "--repeats", "0", "--quiet", "--out", "out.csv"}},
        {"bench plot",
         {"bench", "--height", "h.png", "--rays", "4", "--polar", "60", "--techniques", "pom",
          "--defaults-only", "--repeats", "0", "--quiet", "--out", "-", "--plot", "out.svg"}},
        {"stability csv", {"stability", "--case", "flat-0", "--rays", "4", "--csv", "out.csv"}},
        {"shader", {"shader", "--technique", "pom", "--out", "out.frag"}},
        {"render", {"render", "--height", "h.png", "--size", "32", "--out", "out.png"}},
    };
}

QString outputOf(const QStringList& args) {
    for (const char* option : {"--plot", "--csv", "--out"}) {
        const int at = static_cast<int>(args.indexOf(option));
        if (at >= 0 && args.at(at + 1) != "-")
            return args.at(at + 1);
    }
    return {};
}

} // namespace

class FaultDiskTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() {
        // Also after a failed case: a mount left behind would outlive the test.
        unmount(m_temp.path() + "/tmpfs");
        unmount(m_temp.path() + "/readonly");
        printTally("disk");
    }
    void injectedFullDisk_data();
    void injectedFullDisk();
    void realFullDisk();
    void readOnlyFileSystem();
    void exportOnFullDisk();

private:
    // Writes the inputs and a previous version of every output into `folder`.
    void prepare(const QString& folder);
    QTemporaryDir m_temp;
};

void FaultDiskTest::initTestCase() {
    QVERIFY(m_temp.isValid());
}

void FaultDiskTest::prepare(const QString& folder) {
    QVERIFY(writeSample(folder + "/h.png", "noise", 32));
    for (const char* previous :
         {"out.png", "out.exr", "out.tif", "out.csv", "out.svg", "out.frag"}) {
        QFile file(folder + "/" + previous);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray("the previous ") + previous + ", which must survive\n");
    }
}

// Every writer at two of bytes 0 (nothing written), 1 and 57 (part of the file), turn by turn:
// where a file fails is decided in one place, the checked writer every command writes through
// (writeFileAtomically), and every byte is tried under eight writers (PX_FAULTS_ALL=1: all three
// under each).
void FaultDiskTest::injectedFullDisk_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("failAt");
    const QList<int> bytes = {0, 1, 57};
    int writer = 0;
    for (const auto& [name, args] : writers()) {
        for (int b = 0; b < bytes.size(); ++b) {
            if (takesCase(writer, b, static_cast<int>(bytes.size()), 2))
                QTest::newRow(qPrintable(name + " at byte " + QString::number(bytes[b])))
                    << args << bytes[b];
        }
        ++writer;
    }
}

void FaultDiskTest::injectedFullDisk() {
    QFETCH(QStringList, args);
    QFETCH(int, failAt);
    // Prepared once: every case must leave it as it was, which the next case relies on too.
    const QString folder = m_temp.path() + "/injected";
    if (!QDir(folder).exists()) {
        QDir().mkpath(folder);
        prepare(folder);
    }
    PX_EXPECT_CLEAN_FAILURE(folder, args, {"PX_TEST_FAIL_WRITE_AT=" + QString::number(failAt)}, 1,
                            outputOf(args), "No space left on device");
}

void FaultDiskTest::realFullDisk() {
    const QString folder = m_temp.path() + "/tmpfs";
    QString why;
    if (!mountTmpfs(folder, 1024, why))
        QSKIP(qPrintable("cannot mount a tmpfs here (" + why +
                         "): injectedFullDisk covers the same cases"));
    prepare(folder);
    // Fill the disk, so that the first block of every output below overflows it.
    QFile filler(folder + "/filler");
    QVERIFY(filler.open(QIODevice::WriteOnly));
    const QByteArray block(4096, 'f');
    while (filler.write(block) == block.size() && filler.flush()) {
    }
    filler.close();
    for (const auto& [name, args] : writers()) {
        QStringList big = args;
        if (args.first() == "sample") // large enough to overflow what is left
            big[big.indexOf("--size") + 1] = "512";
        PX_EXPECT_CLEAN_FAILURE(folder, big, {}, 1, outputOf(args), "No space left on device");
    }
    unmount(folder);
}

void FaultDiskTest::readOnlyFileSystem() {
    const QString folder = m_temp.path() + "/readonly";
    QString why;
    const bool mounted = mountTmpfs(folder, 4096, why);
    if (!mounted && ::geteuid() == 0)
        QSKIP(qPrintable("root ignores permissions and no tmpfs can be mounted (" + why + ")"));
    if (!mounted)
        QDir().mkpath(folder);
    prepare(folder);
    QCOMPARE(
        runCli(folder, {"export", "--height", "h.png", "--format", "godot", "--out", "earlier"})
            .status,
        0);
    if (mounted)
        QVERIFY(remountReadOnly(folder));
    else
        QFile::setPermissions(folder, QFile::ReadOwner | QFile::ExeOwner);
    const QString reason = mounted ? "Read-only file system" : "Permission denied";
    for (const auto& [name, args] : writers())
        PX_EXPECT_CLEAN_FAILURE(folder, args, {}, 1, outputOf(args), reason);
    // --force over a read-only earlier export: an error, the export as it was, no debris.
    PX_EXPECT_CLEAN_FAILURE(folder,
                            QStringList({"export", "--height", "h.png", "--format", "godot",
                                         "--out", "earlier", "--force"}),
                            {}, 1, "earlier", reason);
    if (mounted)
        unmount(folder);
    else
        QFile::setPermissions(folder, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
}

void FaultDiskTest::exportOnFullDisk() {
    const QString folder = m_temp.path() + "/export";
    QDir().mkpath(folder);
    prepare(folder);
    QCOMPARE(
        runCli(folder, {"export", "--height", "h.png", "--format", "unity", "--out", "earlier"})
            .status,
        0);
    for (const char* format : {"package", "gltf", "godot", "unreal", "unity"}) {
        for (const char* at : {"0", "300"}) {
            PX_EXPECT_CLEAN_FAILURE(
                folder,
                QStringList({"export", "--height", "h.png", "--format", format, "--out", "fresh"}),
                {QString("PX_TEST_FAIL_WRITE_AT=") + at}, 1, "fresh", "No space left on device");
        }
    }
    PX_EXPECT_CLEAN_FAILURE(folder,
                            QStringList({"export", "--height", "h.png", "--format", "unity",
                                         "--out", "earlier", "--force"}),
                            {"PX_TEST_FAIL_WRITE_AT=100"}, 1, "earlier", "No space left on device");
}

PX_FAULTS_MAIN(FaultDiskTest)
#include "FaultDiskTest.moc"

#include "FaultSupport.h"

#include "TestSupport.h"
#include "parallax/image/ImageFile.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QDir>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QMetaMethod>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTest>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>

namespace px::faults {

CliRun runCli(const QString& folder, const QStringList& arguments, const QStringList& environment,
              long long addressSpace) {
    QProcess process;
    if (addressSpace > 0) {
        process.setChildProcessModifier([addressSpace] {
            const rlimit limit{static_cast<rlim_t>(addressSpace),
                               static_cast<rlim_t>(addressSpace)};
            ::setrlimit(RLIMIT_AS, &limit);
        });
    }
    process.setWorkingDirectory(folder);
    process.setProcessChannelMode(QProcess::MergedChannels);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const QString& entry : environment)
        env.insert(entry.section('=', 0, 0), entry.section('=', 1));
    process.setProcessEnvironment(env);
    QElapsedTimer timer;
    timer.start();
    process.start(QStringLiteral(PX_CLI_PATH), arguments);
    process.waitForFinished(300000);
    CliRun run;
    run.seconds = static_cast<double>(timer.nsecsElapsed()) / 1e9;
    run.output = QString::fromUtf8(process.readAll());
    if (process.exitStatus() == QProcess::CrashExit) {
        // QProcess does not say which signal: a run ends by SIGKILL only where a test asked.
        run.signal = -1;
    } else {
        run.status = process.exitCode();
    }
    return run;
}

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(file.write(bytes), bytes.size());
}

bool writeSample(const QString& path, const QString& name, int size, unsigned seed, int bits) {
    const std::optional<ProceduralMap> kind = parseProceduralMap(name.toStdString());
    const Result<PixelFormat> format = pixelFormatFromBits(bits);
    if (!kind || !format) {
        qWarning("no sample %s at %d bits", qPrintable(name), bits);
        return false;
    }
    ImageWriteOptions options;
    options.format = *format;
    const Status written = writeImage(
        path.toStdString(), makeProceduralMap(*kind, size, size, seed).toImage(), options);
    if (!written)
        qWarning("%s", written.error().message.c_str());
    return static_cast<bool>(written);
}

bool takesCase(int a, int b, int count, int per) {
    static const bool all = qEnvironmentVariableIntValue("PX_FAULTS_ALL") == 1;
    return all || ((b - a) % count + count) % count < per;
}

bool copyFolder(const QString& from, const QString& to) {
    std::error_code ec;
    std::filesystem::remove_all(to.toStdString(), ec);
    if (!ec)
        std::filesystem::copy(from.toStdString(), to.toStdString(),
                              std::filesystem::copy_options::recursive |
                                  std::filesystem::copy_options::copy_symlinks,
                              ec);
    if (ec)
        qWarning("copying %s to %s: %s", qPrintable(from), qPrintable(to), ec.message().c_str());
    return !ec;
}

QMap<QString, QByteArray> snapshot(const QString& folder) {
    QMap<QString, QByteArray> entries;
    QDirIterator it(folder, QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot,
                    QDirIterator::Subdirectories);
    const QDir root(folder);
    while (it.hasNext()) {
        const QString path = it.next();
        const QString name = root.relativeFilePath(path);
        // By lstat: a link is its target's name, a FIFO or device its kind (opening a FIFO to
        // read it would wait for a writer forever).
        struct stat st {};
        if (::lstat(path.toLocal8Bit().constData(), &st) != 0)
            continue;
        if (S_ISDIR(st.st_mode)) {
            entries.insert(name + "/", QByteArray());
        } else if (S_ISLNK(st.st_mode)) {
            entries.insert(name, "<link to " + QFile::symLinkTarget(path).toUtf8() + ">");
        } else if (!S_ISREG(st.st_mode)) {
            entries.insert(name, "<special " + QByteArray::number(st.st_mode & S_IFMT) + " " +
                                     QByteArray::number(static_cast<qulonglong>(st.st_rdev)) + ">");
        } else {
            QFile file(path);
            if (file.open(QIODevice::ReadOnly))
                entries.insert(name, file.readAll());
        }
    }
    return entries;
}

QString difference(const QMap<QString, QByteArray>& before,
                   const QMap<QString, QByteArray>& after) {
    QStringList lines;
    for (auto it = before.begin(); it != before.end(); ++it) {
        if (!after.contains(it.key()))
            lines << "removed: " + it.key();
        else if (after.value(it.key()) != it.value())
            lines << "changed: " + it.key();
    }
    for (auto it = after.begin(); it != after.end(); ++it) {
        if (!before.contains(it.key()))
            lines << "left behind: " + it.key();
    }
    return lines.join('\n');
}

Tally& tally() {
    static Tally t;
    return t;
}

void record(const CliRun& run, bool clearError, bool crashed, long long lost) {
    Q_UNUSED(run);
    Tally& t = tally();
    ++t.cases;
    t.clearErrors += clearError ? 1 : 0;
    t.crashes += crashed ? 1 : 0;
    t.bytesLost += lost;
}

long long bytesLost(const QMap<QString, QByteArray>& before,
                    const QMap<QString, QByteArray>& after) {
    long long lost = 0;
    for (auto it = before.begin(); it != before.end(); ++it) {
        if (!after.contains(it.key()) || after.value(it.key()) != it.value())
            lost += it.value().size();
    }
    return lost;
}

void printTally(const char* suite) {
    const Tally& t = tally();
    std::printf("FAULTS %s: %d cases, %d clear errors, %d crashes, %lld bytes lost\n", suite,
                t.cases, t.clearErrors, t.crashes, t.bytesLost);
    std::fflush(stdout);
}

bool mountTmpfs(const QString& folder, int kilobytes, QString& why) {
    QDir().mkpath(folder);
    const QByteArray options = "size=" + QByteArray::number(kilobytes) + "k";
    if (::mount("tmpfs", folder.toLocal8Bit().constData(), "tmpfs", 0, options.constData()) != 0) {
        why = QString::fromLocal8Bit(std::strerror(errno));
        return false;
    }
    return true;
}

bool remountReadOnly(const QString& folder) {
    return ::mount("tmpfs", folder.toLocal8Bit().constData(), "tmpfs", MS_REMOUNT | MS_RDONLY,
                   nullptr) == 0;
}

void unmount(const QString& folder) {
    ::umount2(folder.toLocal8Bit().constData(), MNT_DETACH);
}

int execShard(QObject* test, int argc, char** argv) {
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    const px::test::TestShard shard = px::test::testShard();
    if (shard.count <= 1)
        return QTest::qExec(test, arguments);
    // The shard's functions, in declaration order.
    const QMetaObject* meta = test->metaObject();
    const QStringList fixtures = {"initTestCase", "cleanupTestCase", "init", "cleanup"};
    QStringList all, taken;
    for (int m = meta->methodOffset(); m < meta->methodCount(); ++m) {
        const QMetaMethod method = meta->method(m);
        const QString name = QString::fromLatin1(method.name());
        if (method.methodType() != QMetaMethod::Slot || method.access() != QMetaMethod::Private ||
            fixtures.contains(name) || name.endsWith("_data"))
            continue;
        if (shard.takes(static_cast<std::size_t>(all.size())))
            taken << name;
        all << name;
    }
    // Functions named on the command line ("name" or "name:row") run where the shard takes them;
    // without names, the shard's own run.
    QStringList kept = {arguments.front()};
    qsizetype named = 0, running = 0;
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString function = arguments[i].section(':', 0, 0);
        const bool isFunction = all.contains(function);
        named += isFunction ? 1 : 0;
        if (!isFunction || taken.contains(function)) {
            kept << arguments[i];
            running += isFunction ? 1 : 0;
        }
    }
    if (named == 0) {
        kept << taken;
        running = taken.size();
    }
    if (running == 0) // no names would run them all
        qFatal("shard %zu/%zu takes none of the %lld test functions%s", shard.index, shard.count,
               static_cast<long long>(named == 0 ? all.size() : named), named == 0 ? "" : " named");
    return QTest::qExec(test, kept);
}

} // namespace px::faults

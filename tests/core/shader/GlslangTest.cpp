// Every variant's fragment stage and each distinct vertex stage through glslangValidator, the
// Khronos reference front end: the shaders are GLSL 4.30 core as the specification reads it, not
// only as Mesa accepts it.

#include "TestSupport.h"
#include "parallax/shader/ShaderGenerator.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <map>
#include <set>

using namespace px;

class GlslangTest : public QObject {
    Q_OBJECT

private slots:
    void everyVariantValidates();
    void aBrokenShaderIsCaught();
};

namespace {

struct Validation {
    QString failure;   // the validator's output on failure, empty on success
    int validated = 0; // files it reports having checked
};

using SourceMap = std::map<QString, std::vector<std::string>>; // file -> its #line sources

// Given several files the validator names each before its messages: only the blocks of the
// files with errors are kept (a failure deep in a batch is not cut off behind the names of the
// files that passed), their positions as "shaders/FILE:LINE".
QString failingBlocks(const QString& out, const QStringList& files, const SourceMap& sources) {
    QString blocks, current;
    const std::vector<std::string>* fileSources = nullptr;
    bool failed = false;
    auto flush = [&] {
        blocks += failed ? current : QString();
        current.clear();
        failed = false;
    };
    for (const QString& line : out.split('\n')) {
        if (files.contains(line.trimmed())) {
            flush();
            current = line.trimmed() + '\n';
            const auto it = sources.find(line.trimmed());
            fileSources = it == sources.end() ? nullptr : &it->second;
            continue;
        }
        if (line.trimmed().isEmpty())
            continue;
        current +=
            (fileSources ? QString::fromStdString(mapCompilerLog(line.toStdString(), *fileSources))
                         : line) +
            '\n';
        failed = failed || line.startsWith("ERROR");
    }
    flush();
    return blocks.isEmpty() ? out : blocks;
}

// Runs the validator on a batch of files. Given several files it names each one it checked on
// stdout; those lines are counted, independently of how many files the test wrote.
Validation validate(const QStringList& files, const SourceMap& sources = {}) {
    QProcess p;
    p.start(PX_GLSLANG, files);
    if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit)
        return {QString("could not run %1: %2").arg(PX_GLSLANG, p.errorString()), 0};
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    if (p.exitCode() != 0)
        return {failingBlocks(out, files, sources) + QString::fromUtf8(p.readAllStandardError()),
                0};
    if (files.size() == 1)
        return {{}, 1}; // a single file is not named: its exit status says it was checked
    int validated = 0;
    for (const QString& line : out.split('\n'))
        validated += files.contains(line.trimmed()) ? 1 : 0;
    return {{}, validated};
}

} // namespace

void GlslangTest::everyVariantValidates() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QStringList batch;
    SourceMap sources;
    int written = 0, validated = 0;
    auto flush = [&]() -> QString {
        const Validation v = batch.isEmpty() ? Validation{} : validate(batch, sources);
        validated += v.validated;
        batch.clear();
        sources.clear();
        return v.failure;
    };
    // ctest runs the shards in parallel (TestSupport.h).
    const test::TestShard shard = test::testShard();
    const std::vector<VariantKey> all = allVariants();
    std::set<std::string> vertexStages; // shared by many variants: each validated once
    for (std::size_t i = shard.index; i < all.size(); i += shard.count) {
        const VariantKey& k = all[i];
        Result<GeneratedProgram> p = generateProgram(k);
        QVERIFY2(p.ok(), k.name().c_str());
        auto add = [&](const std::string& name, const GeneratedShader& shader) {
            const QString path = dir.filePath(QString::fromStdString(name));
            std::ofstream(path.toStdString()) << shader.text;
            batch << path;
            sources[path] = shader.sources;
            ++written;
        };
        add(k.name() + ".frag", p->fragment);
        if (vertexStages.insert(p->vertexKey.name()).second)
            add(p->vertexKey.name() + ".vert", p->vertex);
        if (batch.size() >= 600) {
            const QString failure = flush();
            QVERIFY2(failure.isEmpty(), qPrintable(failure.left(4000)));
        }
    }
    const QString failure = flush();
    QVERIFY2(failure.isEmpty(), qPrintable(failure.left(4000)));
    // Every variant of the shard's fragment stage and each distinct vertex stage reached the
    // validator and was checked by it.
    const int variants =
        static_cast<int>((all.size() - shard.index + shard.count - 1) / shard.count);
    QVERIFY(variants > 0);
    QCOMPARE(written, variants + static_cast<int>(vertexStages.size()));
    QCOMPARE(validated, written);
}

// The check can fail: a shader the reference compiler rejects is reported.
void GlslangTest::aBrokenShaderIsCaught() {
    QTemporaryDir dir;
    const QString path = dir.filePath("broken.frag");
    std::ofstream(path.toStdString())
        << "#version 430 core\nout vec4 c;\nvoid main() { c = vec(1); }\n";
    QVERIFY(!validate({path}).failure.isEmpty());
}

QTEST_APPLESS_MAIN(GlslangTest)
#include "GlslangTest.moc"

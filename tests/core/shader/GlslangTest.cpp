// Every variant, both stages, through glslangValidator, the Khronos reference front end: the
// shaders are GLSL 4.30 core as the specification reads it, not only as Mesa accepts it.

#include "parallax/shader/ShaderGenerator.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>

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

// Runs the validator on a batch of files. Given several files it names each one it checked on
// stdout; those lines are counted, independently of how many files the test wrote.
Validation validate(const QStringList& files) {
    QProcess p;
    p.start(PX_GLSLANG, files);
    if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit)
        return {QString("could not run %1: %2").arg(PX_GLSLANG, p.errorString()), 0};
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    if (p.exitCode() != 0)
        return {out + QString::fromUtf8(p.readAllStandardError()), 0};
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
    int written = 0, validated = 0;
    auto flush = [&]() -> QString {
        const Validation v = batch.isEmpty() ? Validation{} : validate(batch);
        validated += v.validated;
        batch.clear();
        return v.failure;
    };
    // PX_TEST_SHARD=i/n takes every n-th variant from the i-th: ctest runs the shards in parallel.
    int shard = 0, shards = 1;
    if (const QByteArray s = qgetenv("PX_TEST_SHARD"); !s.isEmpty()) {
        shard = s.split('/').value(0).toInt();
        shards = std::max(1, s.split('/').value(1).toInt());
    }
    QVERIFY(shard >= 0 && shard < shards);
    const std::vector<VariantKey> all = allVariants();
    for (std::size_t i = shard; i < all.size(); i += shards) {
        const VariantKey& k = all[i];
        Result<GeneratedProgram> p = generateProgram(k);
        QVERIFY2(p.ok(), k.name().c_str());
        for (const auto& [stage, shader] :
             {std::pair{".vert", &p->vertex}, std::pair{".frag", &p->fragment}}) {
            const QString path = dir.filePath(QString::fromStdString(k.name()) + stage);
            std::ofstream(path.toStdString()) << shader->text;
            batch << path;
            ++written;
        }
        if (batch.size() >= 600) {
            const QString failure = flush();
            QVERIFY2(failure.isEmpty(), qPrintable(failure.left(4000)));
        }
    }
    const QString failure = flush();
    QVERIFY2(failure.isEmpty(), qPrintable(failure.left(4000)));
    // Every variant of the shard, both stages, reached the validator and was checked by it.
    const int variants = static_cast<int>((all.size() - shard + shards - 1) / shards);
    QVERIFY(variants > 0);
    QCOMPARE(written, 2 * variants);
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

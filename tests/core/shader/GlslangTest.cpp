// Every variant's fragment stage and every distinct vertex stage through glslangValidator, the
// Khronos reference front end: the shaders are GLSL 4.30 core as the specification reads it, not
// only as Mesa accepts it.

#include "parallax/shader/ShaderGenerator.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <set>

using namespace px;

class GlslangTest : public QObject {
    Q_OBJECT

private slots:
    void everyVariantValidates();
    void aBrokenShaderIsCaught();
};

namespace {

// Runs the validator on a batch of files; returns its output on failure, empty on success.
QString validate(const QStringList& files) {
    QProcess p;
    p.start(PX_GLSLANG, files);
    if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit)
        return QString("could not run %1: %2").arg(PX_GLSLANG, p.errorString());
    if (p.exitCode() != 0)
        return QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError());
    return {};
}

} // namespace

void GlslangTest::everyVariantValidates() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QStringList batch;
    int files = 0;
    auto flush = [&]() -> QString {
        QString failure = batch.isEmpty() ? QString() : validate(batch);
        batch.clear();
        return failure;
    };
    // PX_TEST_SHARD=i/n takes every n-th variant from the i-th: ctest runs the shards in parallel.
    int shard = 0, shards = 1;
    if (const QByteArray s = qgetenv("PX_TEST_SHARD"); !s.isEmpty()) {
        shard = s.split('/').value(0).toInt();
        shards = std::max(1, s.split('/').value(1).toInt());
    }
    const std::vector<VariantKey> all = allVariants();
    int expected = 0;
    std::set<std::string> vertexStages; // shared by many variants: each validated once
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (static_cast<int>(i % shards) != shard)
            continue;
        const VariantKey& k = all[i];
        Result<GeneratedProgram> p = generateProgram(k);
        QVERIFY2(p.ok(), k.name().c_str());
        auto add = [&](const std::string& name, const GeneratedShader& shader) {
            const QString path = dir.filePath(QString::fromStdString(name));
            std::ofstream(path.toStdString()) << shader.text;
            batch << path;
            ++files;
        };
        ++expected;
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
    QCOMPARE(files, expected + static_cast<int>(vertexStages.size()));
    QVERIFY(files > 0);
}

// The check can fail: a shader the reference compiler rejects is reported.
void GlslangTest::aBrokenShaderIsCaught() {
    QTemporaryDir dir;
    const QString path = dir.filePath("broken.frag");
    std::ofstream(path.toStdString())
        << "#version 430 core\nout vec4 c;\nvoid main() { c = vec(1); }\n";
    QVERIFY(!validate({path}).isEmpty());
}

QTEST_APPLESS_MAIN(GlslangTest)
#include "GlslangTest.moc"

// Values that read as something else than they say: a float texel at 3e38 (finite, but it
// overflows what the renderer computes, and one infinite texel blackens a whole channel), a JSON
// key given twice, a seed with a leading zero (not octal), a relative XDG_CACHE_HOME (invalid by
// the XDG spec: ignored, never a cache folder wherever the command runs), a material named in
// another script (file names keep it, readable).

#include "FaultSupport.h"
#include "parallax/image/ImageFile.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace px::faults;

class FaultValuesTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { printTally("values"); }
    void hugeFloatTexelRefused_data();
    void hugeFloatTexelRefused();
    void duplicateJsonKeyRefused();
    void seedIsDecimal();
    void relativeXdgCacheHomeIgnored();
    void namesInAnyScriptKept();

private:
    QString m_dir;
    QTemporaryDir m_temp;
};

void FaultValuesTest::initTestCase() {
    QVERIFY(m_temp.isValid());
    m_dir = m_temp.path();
    QVERIFY(writeSample(m_dir + "/h.png", "noise", 32));
    // Float EXRs, an albedo 8 x 8 and an environment 16 x 8, at 0.5 but for texel (3, 2) at 3e38.
    for (const auto& [name, width] : {std::pair{"huge.exr", 8}, {"huge-env.exr", 16}}) {
        px::Image image(width, 8, 3);
        for (float& v : image.pixels)
            v = 0.5f;
        image.at(3, 2, 0) = 3e38f;
        px::ImageWriteOptions options;
        options.format = px::PixelFormat::Float;
        QVERIFY(px::writeImage((m_dir + "/" + name).toStdString(), image, options).ok());
    }
    writeFile(m_dir + "/huge.json", R"({"format": "parallax-studio-material", "version": 1,
 "maps": {"height": "h.png", "albedo": "huge.exr"}})");
}

void FaultValuesTest::hugeFloatTexelRefused_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("reason");
    QTest::newRow("an albedo") << QStringList{"render", "--height", "h.png", "--albedo", "huge.exr",
                                              "--size", "16",       "--out", "r.png"}
                               << "huge.exr"
                               << "texel \\(3, 2\\) channel 0 holds 3e\\+38, beyond the 100 a "
                                  "colour map may hold";
    QTest::newRow("a material's albedo")
        << QStringList{"render", "--material", "huge.json", "--size", "16", "--out", "r.png"}
        << "huge.exr"
        << "holds 3e\\+38, beyond the 100 a colour map may hold";
    QTest::newRow("an environment")
        << QStringList{"render", "--height", "h.png", "--environment", "huge-env.exr",
                       "--size", "16",       "--out", "r.png"}
        << "huge-env.exr"
        << "texel \\(3, 2\\) channel 0 holds 3e\\+38, beyond the 1e\\+20 an environment's radiance "
           "may reach";
}

void FaultValuesTest::hugeFloatTexelRefused() {
    QFETCH(QStringList, args);
    QFETCH(QString, file);
    QFETCH(QString, reason);
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, file, reason);
}

void FaultValuesTest::duplicateJsonKeyRefused() {
    writeFile(m_dir + "/dup.json", R"({"format": "parallax-studio-material", "version": 1,
 "maps": {"height": "h.png"}, "technique": {"name": "pom", "name": "exact"}})");
    PX_EXPECT_CLEAN_FAILURE(
        m_dir, (QStringList{"render", "--material", "dup.json", "--size", "16", "--out", "r.png"}),
        {}, 1, "dup.json", "/technique/name: the key appears twice in one object");
}

// "--seed 010" is ten, as written: the same map as --seed 10, another than --seed 8 (which octal
// would make it); a number that is not decimal is a usage error.
void FaultValuesTest::seedIsDecimal() {
    for (const char* seed : {"010", "10", "8"})
        QCOMPARE(runCli(m_dir, {"sample", "noise", "--size", "16", "--seed", seed, "--out",
                                QString("seed-%1.png").arg(seed)})
                     .status,
                 0);
    const auto files = snapshot(m_dir);
    QCOMPARE(files.value("seed-010.png"), files.value("seed-10.png"));
    QVERIFY(files.value("seed-010.png") != files.value("seed-8.png"));
    PX_EXPECT_CLEAN_FAILURE(
        m_dir, (QStringList{"sample", "noise", "--seed", "0x10", "--out", "seed-hex.png"}), {}, 2,
        "0x10", "--seed: '0x10' is not a number");
}

// A relative XDG_CACHE_HOME is invalid (the XDG base directory spec): the default under HOME is
// used, and nothing appears in the folder the command runs in.
void FaultValuesTest::relativeXdgCacheHomeIgnored() {
    const QString home = m_temp.path() + "/home";
    QDir().mkpath(home);
    QDir().mkpath(m_dir + "/run");
    QVERIFY(QFile::copy(m_dir + "/h.png", m_dir + "/run/h.png"));
    const auto before = snapshot(m_dir + "/run");
    const CliRun run =
        runCli(m_dir + "/run",
               {"recommend", "--height", "h.png", "--max-polar", "60", "--techniques", "cone"},
               {"XDG_CACHE_HOME=relative-cache", "HOME=" + home});
    QVERIFY2(run.status == 0, qPrintable(run.output));
    QCOMPARE(difference(before, snapshot(m_dir + "/run")), QString());
    QVERIFY2(!QDir(home + "/.cache/parallax-studio/cone-maps").entryList({"cone-*"}).isEmpty(),
             qPrintable(run.output));
    record(run, true, false, 0);
}

// A material named in another script keeps its name in the files it exports (UTF-8), spaces and
// punctuation made '_', never a run of '_' for every byte.
void FaultValuesTest::namesInAnyScriptKept() {
    const QString name = QString::fromUtf8("Ünçød 材質/1");
    const CliRun run = runCli(m_dir, {"export", "--height", "h.png", "--name", name, "--format",
                                      "gltf", "--out", "named"});
    QVERIFY2(run.status == 0, qPrintable(run.output));
    const QStringList files = QDir(m_dir + "/named").entryList(QDir::Files);
    QVERIFY2(files.contains(QString::fromUtf8("Ünçød_材質_1.gltf")), qPrintable(files.join(' ')));
    QVERIFY2(files.contains(QString::fromUtf8("Ünçød_材質_1_height.png")),
             qPrintable(files.join(' ')));
    record(run, true, false, 0);
}

QTEST_GUILESS_MAIN(FaultValuesTest)
#include "FaultValuesTest.moc"

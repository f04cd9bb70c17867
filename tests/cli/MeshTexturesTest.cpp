// `render --mesh m.obj --out TEXTURE` never writes over a texture the mesh's material library
// names, however the library is written: LF, CRLF or CR-only line ends, names with spaces
// ("map_Kd my tex.png", which Assimp reads as one name), options before the name, each texture
// keyword. The texture is the one Assimp reads (core/src/mesh/ObjCheck.cpp before it,
// MeshLoader's record of the scene's textures after). Refused before any work: the texture is
// byte-identical afterwards and nothing is left beside it. Seeds vary per run (PX_TEST_SEED=N).

#include "Cli.h"

#include <QtTest>
#include <cstdlib>
#include <iostream>
#include <random>
#include <sstream>

class MeshTexturesTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void textureNeverOverwritten_data();
    void textureNeverOverwritten();

private:
    QTemporaryDir m_dir;
    unsigned m_seed = 0;
};

namespace {

struct Outcome {
    int status = 0;
    std::string errors;
};

Outcome runCli(const QStringList& args) {
    std::vector<std::string> words{"parallax-cli"};
    for (const QString& a : args)
        words.push_back(a.toStdString());
    std::vector<char*> argv;
    argv.reserve(words.size());
    for (std::string& w : words)
        argv.push_back(w.data());
    std::ostringstream captured;
    std::streambuf* old = std::cerr.rdbuf(captured.rdbuf());
    const int status = px::cli::run(static_cast<int>(argv.size()), argv.data());
    std::cerr.rdbuf(old);
    return {status, captured.str()};
}

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
}

QByteArray readFile(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

void MeshTexturesTest::initTestCase() {
    QVERIFY(m_dir.isValid());
    const char* given = std::getenv("PX_TEST_SEED");
    m_seed = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                   : std::random_device{}() % 100000u;
    qInfo("seed %u (PX_TEST_SEED=%u repeats it)", m_seed, m_seed);
    QVERIFY(QDir::setCurrent(m_dir.path()));
    const Outcome h = runCli({"sample", "noise", "--size", "16", "--out", "h.png"});
    QVERIFY2(h.status == 0, h.errors.c_str());
}

void MeshTexturesTest::textureNeverOverwritten_data() {
    QTest::addColumn<QByteArray>("library");
    QTest::addColumn<QString>("texture");
    std::mt19937 random(m_seed);
    const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
    const char* ends[] = {"\n", "\r\n", "\r"};
    const char* keywords[] = {"map_Kd", "map_Ka", "map_Bump", "bump", "map_d", "disp", "norm"};
    const char* names[] = {"my tex.png", "tex.png", "a b  c.png", "albedo map (1).png"};
    const char* options[] = {"", "-bm 0.5 ", "-s 1 1 1 ", "-clamp on "};
    for (int e = 0; e < 3; ++e) {
        for (int n = 0; n < 4; ++n) {
            const QString name = names[n];
            const QByteArray end = ends[e];
            const char* keyword = keywords[pick(7)];
            const char* option = options[pick(4)];
            const QByteArray library = "# material" + end + "newmtl m" + end + "Kd 1 1 1" + end +
                                       keyword + " " + option + name.toUtf8() + end;
            QTest::newRow(qPrintable(QString("%1, %2 %3'%4'")
                                         .arg(e == 0   ? "LF"
                                              : e == 1 ? "CRLF"
                                                       : "CR only")
                                         .arg(keyword)
                                         .arg(option)
                                         .arg(name)))
                << library << name;
        }
    }
}

void MeshTexturesTest::textureNeverOverwritten() {
    QFETCH(QByteArray, library);
    QFETCH(QString, texture);
    const QString folder = m_dir.filePath("mesh");
    QDir(folder).removeRecursively();
    QVERIFY(QDir().mkpath(folder));
    writeFile(folder + "/m.obj", "mtllib m.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
                                 "vt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
    writeFile(folder + "/m.mtl", library);
    const QByteArray bytes = "the artist's texture, not a PNG the run wrote";
    writeFile(folder + "/" + texture, bytes);
    const QStringList before = QDir(folder).entryList(QDir::Files | QDir::Hidden);
    const Outcome run = runCli({"render", "--height", "h.png", "--mesh", "mesh/m.obj", "--size",
                                "16", "--out", "mesh/" + texture});
    QVERIFY2(run.status == 1, run.errors.c_str());
    QVERIFY2(run.errors.starts_with("error: "), run.errors.c_str());
    QVERIFY2(QString::fromStdString(run.errors).contains("a texture of mesh mesh/m.obj"),
             run.errors.c_str());
    QVERIFY2(QString::fromStdString(run.errors).contains(texture), run.errors.c_str());
    QCOMPARE(readFile(folder + "/" + texture), bytes);
    QCOMPARE(QDir(folder).entryList(QDir::Files | QDir::Hidden), before);
}

QTEST_GUILESS_MAIN(MeshTexturesTest)
#include "MeshTexturesTest.moc"

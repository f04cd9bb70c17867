// What a mesh file claims is bounded before Assimp allocates, for every use Assimp makes of it
// (core/src/mesh/MeshFileChecks.h): glTF accessors of any primitive mode, morph targets, skins
// and animation samplers; JSON nesting; node hierarchies; OBJ statements cut and read as Assimp's
// ObjFileParser does (CR-only line ends, `\` continuation lines, any 'f'/'l'/'p' keyword). The OBJ
// counts are checked against Assimp itself on generated files (seeds vary per run; PX_TEST_SEED=N
// repeats one). The checks run on files with no data behind their claims, under an address-space
// limit: a check that let one through would fail here by Assimp running out of memory (or by the
// stack overflow of a deep JSON), not by taking the machine's.

#include "MeshFileChecks.h"
#include "parallax/io/Inputs.h"
#include "parallax/mesh/MeshLoader.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sys/resource.h>

using namespace px;

class MeshBoundsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void gltfClaimsBounded_data();
    void gltfClaimsBounded();
    void gltfWithinTheLimitsLoads_data();
    void gltfWithinTheLimitsLoads();
    void objCountsAgreeWithAssimp();
    void objStatementsBounded_data();
    void objStatementsBounded();

private:
    std::string write(const std::string& name, const std::string& bytes) const;
    Status check(const std::string& path, std::size_t maxTriangles) const;
    QTemporaryDir m_dir;
    unsigned m_seed = 0;
};

namespace {

unsigned runSeed() {
    const char* given = std::getenv("PX_TEST_SEED");
    return given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                 : std::random_device{}() % 100000u;
}

// One triangle with uv, its buffer FILE.bin: positions (36 bytes) then uv (24 bytes).
std::string triangleBuffer() {
    const float data[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
    return std::string(reinterpret_cast<const char*>(data), sizeof data);
}

// A glTF with the triangle as mesh 0 (accessors 0: POSITION, 1: TEXCOORD_0), node 0 drawing it;
// `accessors`, `meshes`, `rest` append to the arrays and the document.
std::string gltf(const std::string& bin, const std::string& accessors = {},
                 const std::string& primitives = {}, const std::string& rest = {},
                 const std::string& nodes = R"({"mesh": 0})") {
    return R"({"asset": {"version": "2.0"},
 "buffers": [{"uri": ")" +
           bin + R"(", "byteLength": 60}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
               {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"})" +
           accessors + R"(],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}})" +
           primitives +
           R"(]}],
 "nodes": [)" +
           nodes + R"(], "scenes": [{"nodes": [0]}], "scene": 0)" + rest + "}";
}

// An accessor of `count` elements with no buffer view (zeros): no bytes behind any of them.
std::string zeros(std::uint64_t count, const char* type = "VEC3") {
    return R"(, {"componentType": 5126, "count": )" + std::to_string(count) + R"(, "type": ")" +
           type + "\"}";
}

} // namespace

void MeshBoundsTest::initTestCase() {
    QVERIFY(m_dir.isValid());
    m_seed = runSeed();
    qInfo("seed %u (PX_TEST_SEED=%u repeats it)", m_seed, m_seed);
    write("tri.bin", triangleBuffer());
    // The address space this process has, plus 1.5 GiB: enough for every legitimate load here,
    // far less than any claim below would make Assimp allocate.
    std::ifstream status("/proc/self/status");
    std::uint64_t kib = 0;
    for (std::string line; std::getline(status, line);) {
        if (line.starts_with("VmSize:"))
            kib = std::strtoull(line.c_str() + 7, nullptr, 10);
    }
    QVERIFY(kib > 0);
    const rlimit limit{(kib << 10) + (3ull << 29), RLIM_INFINITY};
    QVERIFY(setrlimit(RLIMIT_AS, &limit) == 0);
}

std::string MeshBoundsTest::write(const std::string& name, const std::string& bytes) const {
    std::string path = m_dir.filePath(QString::fromStdString(name)).toStdString();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

// The checks before Assimp alone, as loadMesh runs them.
Status MeshBoundsTest::check(const std::string& path, std::size_t maxTriangles) const {
    Result<InputFile> file = InputFile::open(path);
    if (!file)
        return file.error();
    Result<mesh::MeshScope> scope = mesh::MeshScope::make(path, {});
    if (!scope)
        return scope.error();
    return path.ends_with(".obj") ? mesh::checkObj(*file, *scope, maxTriangles)
                                  : mesh::checkGltf(*file, *scope, maxTriangles);
}

void MeshBoundsTest::gltfClaimsBounded_data() {
    QTest::addColumn<QString>("document");
    QTest::addColumn<int>("maxTriangles");
    QTest::addColumn<QString>("reason");
    std::mt19937 random(m_seed);
    const auto between = [&](std::uint64_t a, std::uint64_t b) {
        return std::uniform_int_distribution<std::uint64_t>(a, b)(random);
    };
    const QString values = "its accessors hold more than [0-9]+ values \\(meshes, morph targets, "
                           "skins and animations together\\)";
    const QString faces = " points, lines and triangles, more than the preview's limit of ";
    // Each primitive mode of a primitive without indices, 4 to 6 million elements (about 50
    // bytes each in Assimp's faces): under the default limit's value budget, over its faces.
    for (int mode = 0; mode <= 3; ++mode) {
        const std::uint64_t n = between(4'100'000, 6'000'000);
        const std::uint64_t made = mode == 0 || mode == 2 ? n : mode == 1 ? n / 2 : n - 1;
        QTest::newRow(qPrintable("mode " + QString::number(mode) + ", " + QString::number(n)))
            << QString::fromStdString(gltf("tri.bin", zeros(n),
                                           R"(, {"attributes": {"POSITION": 2}, "mode": )" +
                                               std::to_string(mode) + "}"))
            << 2'000'000 << QString::number(made) + faces + "2000000";
    }
    // The issue's file: a sparse accessor (one element given, the rest zeros) of 50M points, a
    // few hundred bytes that took Assimp 3.5 GB and 18 s before the checks counted points.
    const std::uint64_t sparse = between(30'000'000, 60'000'000);
    QTest::newRow(qPrintable("sparse POINTS accessor of " + QString::number(sparse)))
        << QString::fromStdString(
               gltf("tri.bin",
                    R"(, {"componentType": 5126, "count": )" + std::to_string(sparse) +
                        R"(, "type": "VEC3", "sparse": {"count": 1, "indices": {"bufferView": 0,
 "componentType": 5125}, "values": {"bufferView": 0}}})",
                    R"(, {"attributes": {"POSITION": 2}, "mode": 0})"))
        << 2'000'000 << QString::number(sparse) + faces + "2000000";
    QTest::newRow("50M points under a small limit")
        << QString::fromStdString(gltf("tri.bin", zeros(50'000'000),
                                       R"(, {"attributes": {"POSITION": 2}, "mode": 0})"))
        << 1000 << values;
    QTest::newRow("triangles over 70M zero vertices")
        << QString::fromStdString(gltf("tri.bin", zeros(between(70'000'000, 100'000'000)),
                                       R"(, {"attributes": {"POSITION": 2}})"))
        << 2'000'000 << values;
    const std::uint64_t keys = between(40'000'000, 80'000'000);
    QTest::newRow(qPrintable("animation sampler of " + QString::number(keys) + " keys"))
        << QString::fromStdString(gltf("tri.bin", zeros(keys, "SCALAR") + zeros(keys, "VEC4"), {},
                                       R"(, "animations": [{"samplers": [{"input": 2, "output": 3}],
 "channels": [{"sampler": 0, "target": {"node": 0, "path": "rotation"}}]}])"))
        << 2'000'000 << values;
    const std::uint64_t sharing = between(2000, 4000);
    std::string channels;
    for (std::uint64_t i = 0; i < sharing; ++i)
        channels += std::string(i ? "," : "") +
                    R"({"sampler": 0, "target": {"node": 0, "path": "translation"}})";
    QTest::newRow(qPrintable(QString::number(sharing) + " channels sharing one sampler"))
        << QString::fromStdString(gltf("tri.bin", zeros(100'000, "SCALAR") + zeros(100'000), {},
                                       R"(, "animations": [{"samplers": [{"input": 2, "output": 3}],
 "channels": [)" + channels + "]}]"))
        << 2'000'000 << values;
    QTest::newRow("skin of 20M inverse bind matrices")
        << QString::fromStdString(gltf("tri.bin", zeros(between(20'000'000, 30'000'000), "MAT4"),
                                       {},
                                       R"(, "skins": [{"inverseBindMatrices": 2, "joints": [0]}])"))
        << 2'000'000 << values;
    std::string targets;
    const std::uint64_t targetCount = between(100, 200);
    for (std::uint64_t i = 0; i < targetCount; ++i)
        targets += std::string(i ? "," : "") + R"({"POSITION": 2})";
    QTest::newRow(qPrintable(QString::number(targetCount) + " morph targets of 2M"))
        << QString::fromStdString(gltf(
               "tri.bin", zeros(2'000'000),
               R"(, {"attributes": {"POSITION": 2}, "mode": 0, "targets": [)" + targets + "]}"))
        << 2'000'000 << values;
    // Nesting: Assimp's JSON parser recurses once a level.
    for (const std::uint64_t depth : {std::uint64_t{1'000'000}, between(300, 100'000)}) {
        QTest::newRow(qPrintable(QString::number(depth) + " nested arrays in extras"))
            << QString::fromStdString(
                   gltf("tri.bin", {}, {},
                        R"(, "extras": )" + std::string(depth, '[') + std::string(depth, ']')))
            << 2'000'000 << "its JSON nests [0-9]+ levels deep, more than the 256";
    }
    QTest::newRow("node cycle") << QString::fromStdString(
                                       gltf("tri.bin", {}, {}, {},
                                            R"({"mesh": 0, "children": [1]}, {"children": [0]})"))
                                << 2'000'000 << "its nodes form a cycle";
    QTest::newRow("node shared by two parents")
        << QString::fromStdString(gltf("tri.bin", {}, {}, {},
                                       R"({"mesh": 0, "children": [2]}, {"children": [2]}, {})"))
        << 2'000'000 << "node 2 is the child of more than one node";
    std::string chain;
    const std::uint64_t length = between(1100, 5000);
    for (std::uint64_t i = 0; i < length; ++i)
        chain += std::string(i ? "," : "") +
                 (i + 1 < length ? R"({"children": [)" + std::to_string(i + 1) + "]}"
                                 : R"({"mesh": 0})");
    QTest::newRow(qPrintable("node chain " + QString::number(length) + " deep"))
        << QString::fromStdString(gltf("tri.bin", {}, {}, {}, chain)) << 2'000'000
        << "its node hierarchy is more than 1024 levels deep";
}

void MeshBoundsTest::gltfClaimsBounded() {
    QFETCH(QString, document);
    QFETCH(int, maxTriangles);
    QFETCH(QString, reason);
    const std::string path = write("claim.gltf", document.toStdString());
    const Status checked = check(path, static_cast<std::size_t>(maxTriangles));
    QVERIFY2(!checked.ok(), "passed the checks before Assimp");
    QVERIFY2(checked.error().message.starts_with(path + ": "), checked.error().message.c_str());
    QVERIFY2(QString::fromStdString(checked.error().message).contains(QRegularExpression(reason)),
             checked.error().message.c_str());
    // loadMesh refuses it the same way, before Assimp (which, under this process's address-space
    // limit, would fail otherwise with another message, or crash).
    MeshLoadOptions options;
    options.maxTriangles = static_cast<std::size_t>(maxTriangles);
    Result<LoadedMesh> loaded = loadMesh(path, options);
    QVERIFY(!loaded.ok());
    QCOMPARE(loaded.error().message, checked.error().message);
}

void MeshBoundsTest::gltfWithinTheLimitsLoads_data() {
    QTest::addColumn<QString>("document");
    // Small versions of each use: the checks count them and let them through.
    QTest::newRow("points beside the triangle") << QString::fromStdString(
        gltf("tri.bin", {}, R"(, {"attributes": {"POSITION": 0}, "mode": 0})"));
    QTest::newRow("lines beside the triangle") << QString::fromStdString(
        gltf("tri.bin", {}, R"(, {"attributes": {"POSITION": 0}, "mode": 3})"));
    // Times from the uv view (0, 0, 1, ...), translations from the positions.
    QTest::newRow("an animation") << QString::fromStdString(gltf(
        "tri.bin", R"(, {"bufferView": 1, "componentType": 5126, "count": 3, "type": "SCALAR"})",
        {}, R"(, "animations": [{"samplers": [{"input": 2, "output": 0}],
 "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}])"));
    QTest::newRow("extras 200 deep, brackets in strings")
        << QString::fromStdString(gltf("tri.bin", {}, {},
                                       R"(, "extras": {"note": "[[[[{{{{\"]]", "deep": )" +
                                           std::string(200, '[') + std::string(200, ']') + "}"));
    QTest::newRow("a node tree") << QString::fromStdString(
        gltf("tri.bin", {}, {}, {}, R"({"children": [1, 2]}, {"mesh": 0}, {"children": [3]}, {})"));
}

void MeshBoundsTest::gltfWithinTheLimitsLoads() {
    QFETCH(QString, document);
    const std::string path = write("fine.gltf", document.toStdString());
    Result<LoadedMesh> loaded = loadMesh(path);
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
    QCOMPARE(loaded->triangles, 1);
}

// Random OBJs with every way of ending a line Assimp knows, `\` continuations, statements Assimp
// skips (a leading blank, comments) and keywords it reads by their first letter: the triangles
// the checks count equal those Assimp makes, so the limit refuses exactly one more.
void MeshBoundsTest::objCountsAgreeWithAssimp() {
    std::mt19937 random(m_seed);
    const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
    int compared = 0;
    for (int round = 0; round < 24; ++round) {
        const char* ends[] = {"\n", "\r\n", "\r", "\r", "\f"};
        const auto end = [&] { return std::string(ends[pick(5)]); };
        // Eight vertices around a circle, uv = position: every fan is convex and non-degenerate.
        std::string text;
        for (int i = 0; i < 8; ++i) {
            const double a = 6.283185307179586 * i / 8;
            text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0" +
                    end();
            text += "vt " + std::to_string(0.5 + 0.5 * std::cos(a)) + " " +
                    std::to_string(0.5 + 0.5 * std::sin(a)) + end();
        }
        const int statements = 20 + pick(200);
        for (int s = 0; s < statements; ++s) {
            const int corners = 3 + pick(6), first = pick(8);
            const char* keywords[] = {"f", "f", "f", "fo", " f", "# f", "\tf"};
            std::string line = keywords[pick(7)];
            for (int c = 0; c < corners; ++c) {
                const int index = (first + c) % 8 + 1;
                // Position and uv, absolute or relative (-8..-1 from the end of the eight).
                const std::string i = pick(2) ? std::to_string(index - 9) : std::to_string(index);
                line += " " + i + "/" + i;
                if (c > 0 && c + 1 < corners && pick(8) == 0)
                    line += pick(2) ? " \\\n" : " \\\r\n"; // joins the next line
            }
            text += line + end();
        }
        const std::string path = write("agree-" + std::to_string(round) + ".obj", text);
        MeshLoadOptions options;
        options.maxTriangles = 1'000'000;
        Result<LoadedMesh> loaded = loadMesh(path, options);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
        QCOMPARE(loaded->droppedTriangles, 0);
        const auto made = static_cast<std::size_t>(loaded->triangles);
        const Status atLimit = check(path, made);
        QVERIFY2(atLimit.ok(), atLimit.ok() ? "" : atLimit.error().message.c_str());
        const Status over = check(path, made - 1);
        QVERIFY2(!over.ok(), qPrintable(QString("round %1: %2 triangles made, the checks let "
                                                "them through a limit of %3")
                                            .arg(round)
                                            .arg(made)
                                            .arg(made - 1)));
        QCOMPARE(over.error().message, path + ": " + std::to_string(made) +
                                           " triangles, more than the preview's limit of " +
                                           std::to_string(made - 1));
        ++compared;
    }
    QCOMPARE(compared, 24);
}

void MeshBoundsTest::objStatementsBounded_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("reason");
    std::mt19937 random(m_seed + 1);
    const int n = std::uniform_int_distribution<int>(1500, 5000)(random);
    const QByteArray head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
    QByteArray cr = QByteArray(head).replace('\n', '\r');
    for (int i = 0; i < n; ++i)
        cr += "f 1/1 2/1 3/1\r";
    QTest::newRow("CR-only line ends") << cr << QString::number(n) + " triangles, more than";
    QByteArray joined = head + "f 1 2";
    for (int i = 0; i < n; ++i)
        joined += " \\\n3";
    QTest::newRow("one face continued over many lines")
        << joined + "\n"
        << QString::number(n) + " triangles, more than";
    QByteArray zeros = head + "f 1 2 3";
    zeros += QByteArray(n, '0') + "3\n";
    QTest::newRow("an index of many leading zeros")
        << zeros << "an index of more than 10 characters";
    QByteArray lines = head;
    for (int i = 0; i < n; ++i)
        lines += (i % 2 ? "l 1 2\n" : "p 1\n");
    QTest::newRow("lines and points") << lines << "points, lines and triangles, more than";
    QByteArray words = head;
    for (int i = 0; i < n; ++i)
        words += "face 1 2 3\n";
    QTest::newRow("a keyword read by its first letter")
        << words << QString::number(n) + " triangles, more than";
    QByteArray vertices = "v 0 0 0\rv 1 0 0\rv 0 1 0\rvt 0 0\rf 1/1 2/1 3/1\r";
    for (int i = 0; i < 3 * n; ++i)
        vertices += "v 1 2 3\r";
    QTest::newRow("CR-only vertices") << vertices << "vertices, more than 1000 triangles";
}

void MeshBoundsTest::objStatementsBounded() {
    QFETCH(QByteArray, text);
    QFETCH(QString, reason);
    const std::string path = write("claim.obj", text.toStdString());
    const Status checked = check(path, 1000);
    QVERIFY2(!checked.ok(), "passed the checks before Assimp");
    QVERIFY2(QString::fromStdString(checked.error().message).contains(reason),
             checked.error().message.c_str());
}

QTEST_GUILESS_MAIN(MeshBoundsTest)
#include "MeshBoundsTest.moc"

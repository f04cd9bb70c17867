// Inputs reached any other way than by name on the command line (a material's maps, a mesh's
// buffers, images and material libraries, an import folder's files, a turntable's frames, an
// earlier export's files), special files as outputs and inputs (FIFO, socket, device, symbolic
// link), and mesh files whose claims exceed what they hold. Each case fails cleanly: the status,
// a message naming the file and the reason, the folder byte for byte as it was, nothing left
// behind; refusals of mesh files run under a 768 MB address-space limit, so a check that came only
// after Assimp's allocations would fail them.

#include "FaultSupport.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/Temporaries.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

using namespace px::faults;

namespace {

constexpr long long kMeshMemory = 768ll << 20;

QByteArray little32(quint32 v) {
    QByteArray b(4, '\0');
    for (int i = 0; i < 4; ++i)
        b[i] = static_cast<char>((v >> (8 * i)) & 0xff);
    return b;
}

// One textured triangle: positions (36 bytes), uvs (24), three 16-bit indices (6, padded to 8).
QByteArray triangleBuffer(quint16 lastIndex = 2) {
    QByteArray b;
    const float p[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
    b.append(reinterpret_cast<const char*>(p), sizeof p);
    const quint16 i[] = {0, 1, lastIndex, 0};
    b.append(reinterpret_cast<const char*>(i), sizeof i);
    return b;
}

QByteArray triangleGltf(const QString& bufferUri, const QString& extra = {},
                        const QString& positionCount = "3", const QString& byteLength = "68") {
    return QString(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2}]}],
 "buffers": [{%1"byteLength": %4}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                 {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                 {"buffer": 0, "byteOffset": 60, "byteLength": 6}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": %3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]},
               {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
               {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"}]%2})")
        .arg(bufferUri.isEmpty() ? QString() : "\"uri\": \"" + bufferUri + "\", ", extra,
             positionCount, byteLength)
        .toUtf8();
}

// A GLB of the triangle whose JSON chunk claims `jsonLength` bytes.
QByteArray triangleGlb(quint32 jsonLength) {
    QByteArray json = triangleGltf({});
    while (json.size() % 4 != 0)
        json.append(' ');
    const QByteArray bin = triangleBuffer();
    QByteArray glb = "glTF" + little32(2) + little32(20 + json.size() + 8 + bin.size());
    glb +=
        little32(jsonLength) + "JSON" + json + little32(bin.size()) + QByteArray("BIN\0", 4) + bin;
    return glb;
}

} // namespace

class FaultReachTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { printTally("reach"); }
    void inputReachedAnotherWay_data();
    void inputReachedAnotherWay();
    void specialFileAsOutput_data();
    void specialFileAsOutput();
    void deviceAsOutput();
    void linkedOutputWrittenThrough();
    void specialFileAsInput_data();
    void specialFileAsInput();
    void fifoInTheConeCacheDoesNotHang();
    void coneCacheEntryIsAnInput();
    void shaderDumpAllTakesNoMaterial();
    void userFileNamedLikeALockKept_data();
    void userFileNamedLikeALockKept();
    void meshReferencesStayInside_data();
    void meshReferencesStayInside();
    void meshClaimsBeyondTheFile_data();
    void meshClaimsBeyondTheFile();
    void exportNeverRemovesAnInput_data();
    void exportNeverRemovesAnInput();

private:
    QString m_dir;
    QTemporaryDir m_temp;
};

void FaultReachTest::initTestCase() {
    QVERIFY(m_temp.isValid());
    m_dir = m_temp.path() + "/work";
    QDir().mkpath(m_dir + "/sub");
    QDir().mkpath(m_dir + "/meshes/inner");
    auto cli = [&](const QStringList& args) { QCOMPARE(runCli(m_dir, args).status, 0); };
    QVERIFY(writeSample(m_dir + "/h.png", "noise", 32));
    QVERIFY(writeSample(m_dir + "/a.png", "bricks", 32, 1, 8));
    QVERIFY(writeSample(m_dir + "/c.png", "stones", 32));
    QVERIFY(writeSample(m_dir + "/other.png", "rivets", 32));
    QVERIFY(writeSample(m_dir + "/t-000.png", "noise", 32, 3));
    QVERIFY(writeSample(m_dir + "/t-001.png", "noise", 32, 4));
    QVERIFY(::link(QString(m_dir + "/h.png").toLocal8Bit(),
                   QString(m_dir + "/hard.png").toLocal8Bit()) == 0);
    // A material naming a height, an albedo and a cone map (pom does not load the cone map).
    writeFile(m_dir + "/m.json",
              R"({"format": "parallax-studio-material", "version": 1, "name": "m",
 "maps": {"height": "h.png", "albedo": "a.png", "cone": "c.png"}, "technique": {"name": "pom"}})");
    writeFile(m_dir + "/sub/m2.json", R"({"format": "parallax-studio-material", "version": 1,
 "maps": {"height": "../h.png"}, "technique": {"name": "pom"}})");
    writeFile(m_dir + "/t.json", R"({"format": "parallax-studio-material", "version": 1,
 "maps": {"height": "h.png", "albedo": "t-001.png"}})");
    // A texture set folder.
    QDir().mkpath(m_dir + "/set");
    QVERIFY(QFile::copy(m_dir + "/h.png", m_dir + "/set/stone_height.png"));
    QVERIFY(QFile::copy(m_dir + "/a.png", m_dir + "/set/stone_albedo.png"));
    writeFile(m_dir + "/set/notes.txt", "the artist's notes\n");
    QVERIFY(QFile::copy(m_dir + "/a.png", m_dir + "/set/stone_preview.jpg")); // not a map
    // Meshes: a triangle with its buffer, its image, a material library and its texture.
    writeFile(m_dir + "/meshes/tri.bin", triangleBuffer());
    writeFile(m_dir + "/meshes/tri.gltf",
              triangleGltf("tri.bin", R"(, "images": [{"uri": "tri_albedo.png"}])"));
    QVERIFY(QFile::copy(m_dir + "/a.png", m_dir + "/meshes/tri_albedo.png"));
    writeFile(m_dir + "/meshes/tri.obj",
              "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
              "vt 0 1\nf 1/1 2/2 3/3\n");
    writeFile(m_dir + "/meshes/tri.mtl", "newmtl m\nmap_Kd tri_albedo.png\n");
    writeFile(m_dir + "/secret.txt", "outside the mesh's folder\n");
    px::Image sky(16, 8, 3); // an environment, twice as wide as high
    for (float& v : sky.pixels)
        v = 0.25f;
    px::ImageWriteOptions skyOptions;
    skyOptions.format = px::PixelFormat::Float;
    QVERIFY(px::writeImage((m_dir + "/sky.exr").toStdString(), sky, skyOptions).ok());
    cli({"render", "--height", "h.png", "--mesh", "meshes/tri.gltf", "--size", "16", "--out",
         "sub/control-gltf.png"});
    cli({"render", "--height", "h.png", "--mesh", "meshes/tri.obj", "--size", "16", "--out",
         "sub/control-obj.png"});
    QFile::remove(m_dir + "/sub/control-gltf.png");
    QFile::remove(m_dir + "/sub/control-obj.png");
}

void FaultReachTest::inputReachedAnotherWay_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("reason");
    const QString reads = "which this run reads: refusing to overwrite an input";
    QTest::newRow("render: the material's height map")
        << QStringList{"render", "--material", "m.json", "--size", "16", "--out", "h.png"}
        << "h.png"
        << "the height map of m.json[^\\n]*" + reads;
    QTest::newRow("render: its height map spelt ./sub/../")
        << QStringList{"render", "--material", "m.json", "--size", "16", "--out", "./sub/../h.png"}
        << "h.png"
        << "the height map of m.json[^\\n]*" + reads;
    QTest::newRow("render: a hard link to its height map")
        << QStringList{"render", "--material", "m.json", "--size", "16", "--out", "hard.png"}
        << "hard.png" << reads;
    QTest::newRow("render: a map it names but does not load")
        << QStringList{"render", "--material", "m.json", "--size", "16", "--out", "c.png"}
        << "c.png"
        << "the cone map of m.json[^\\n]*" + reads;
    QTest::newRow("render: a material in another folder")
        << QStringList{"render", "--material", "sub/m2.json", "--size", "16", "--out", "h.png"}
        << "h.png"
        << "the height map of sub/m2.json[^\\n]*" + reads;
    QTest::newRow("recommend --out: the albedo")
        << QStringList{"recommend", "--material", "m.json", "--cache", "off", "--out", "a.png"}
        << "a.png"
        << "the albedo map of m.json[^\\n]*" + reads;
    QTest::newRow("shader --out: the albedo")
        << QStringList{"shader", "--material", "m.json", "--out", "a.png"} << "a.png"
        << "the albedo map of m.json[^\\n]*" + reads;
    QTest::newRow("turntable frames: --height and --albedo")
        << QStringList{"render", "--height", "t-000.png", "--albedo", "t-001.png", "--turntable",
                       "2",      "--size",   "16",        "--out",    "t.png"}
        << "t-000.png"
        << "frame 0 of --turntable names the same file as --height t-000.png";
    QTest::newRow("turntable frames: a map of the material")
        << QStringList{"render", "--material", "t.json", "--turntable", "2",
                       "--size", "16",         "--out",  "t.png"}
        << "t-001.png"
        << "frame 1 of --turntable[^\\n]*the albedo map of t.json";
    QTest::newRow("render: the environment map")
        << QStringList{"render", "--height", "h.png", "--environment",   "sky.exr",
                       "--size", "16",       "--out", "./sub/../sky.exr"}
        << "sky.exr"
        << "--out names the same file as --environment sky.exr";
    QTest::newRow("import --force: an image of the set")
        << QStringList{"import", "set", "--out", "set/stone_albedo.png", "--force"}
        << "stone_albedo.png"
        << "an image of the texture set[^\\n]*" + reads;
    QTest::newRow("import --force: an image the set ignores")
        << QStringList{"import", "set", "--out", "set/stone_preview.jpg", "--force"}
        << "stone_preview.jpg"
        << "an image of the texture set[^\\n]*" + reads;
    QTest::newRow("render: a mesh's buffer")
        << QStringList{"render", "--height", "h.png", "--mesh",        "meshes/tri.gltf",
                       "--size", "16",       "--out", "meshes/tri.bin"}
        << "tri.bin"
        << "buffer 0 of mesh meshes/tri.gltf[^\\n]*" + reads;
    QTest::newRow("render: a mesh's image")
        << QStringList{"render", "--height",        "h.png",
                       "--mesh", "meshes/tri.gltf", "--size",
                       "16",     "--out",           "meshes/tri_albedo.png"}
        << "tri_albedo.png"
        << "image 0 of mesh meshes/tri.gltf[^\\n]*" + reads;
    QTest::newRow("render: an OBJ's material library texture")
        << QStringList{"render", "--height",       "h.png",
                       "--mesh", "meshes/tri.obj", "--size",
                       "16",     "--out",          "meshes/tri_albedo.png"}
        << "tri_albedo.png"
        << "a texture of mesh meshes/tri.obj[^\\n]*" + reads;
    QTest::newRow("render: an OBJ's material library")
        << QStringList{"render", "--height", "h.png", "--mesh",        "meshes/tri.obj",
                       "--size", "16",       "--out", "meshes/tri.mtl"}
        << "tri.mtl" << reads;
    QTest::newRow("export --force into the inputs' own folder")
        << QStringList{"export",  "--height", "h.png", "--format",
                       "package", "--out",    ".",     "--force"}
        << ".:"
        << "holds files that no export wrote; refusing to replace it";
}

void FaultReachTest::inputReachedAnotherWay() {
    QFETCH(QStringList, args);
    QFETCH(QString, file);
    QFETCH(QString, reason);
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, file, reason);
}

void FaultReachTest::specialFileAsOutput_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("reason");
    const QString fifo = "is a FIFO \\(named pipe\\), not a regular file: refusing to replace it";
    const QString link = "is a symbolic link \\(to [^)]*\\) to nothing that exists: refusing to "
                         "create a file there";
    const QString linkedFifo = "is a symbolic link to [^ ]*pipe-target, which is a FIFO";
    const QString socket = "is a socket, not a regular file: refusing to replace it";
    const QList<QPair<QString, QStringList>> writers = {
        {"bake", {"bake", "cone", "--height", "h.png", "--out", "OUT.png"}},
        {"sample", {"sample", "noise", "--size", "16", "--out", "OUT.png"}},
        {"trace", {"trace", "--height", "h.png", "--rays", "4", "--out", "OUT.png"}},
        {"render", {"render", "--height", "h.png", "--size", "16", "--out", "OUT.png"}},
        {"shader", {"shader", "--technique", "pom", "--out", "OUT.png"}},
        {"stability", {"stability", "--case", "flat-0", "--rays", "4", "--csv", "OUT.png"}},
        {"import", {"import", "set", "--out", "OUT.png", "--force"}},
    };
    // Every writer meets two of the four kinds, turn by turn, and every kind three or four writers
    // (PX_FAULTS_ALL=1: all four each): the kinds are told apart in one function
    // (checkReplaceable), and a writer that went round it would fail under any of them.
    const QStringList kinds = {"fifo", "link", "dangling", "socket"};
    int w = 0;
    for (const auto& [name, args] : writers) {
        for (int k = 0; k < kinds.size(); ++k) {
            if (!takesCase(w, k, static_cast<int>(kinds.size()), 2))
                continue;
            const QString& kind = kinds[k];
            QStringList a = args;
            a.replaceInStrings("OUT", QString("special-") + kind);
            const QString reason = kind == "fifo"     ? fifo
                                   : kind == "socket" ? socket
                                   : kind == "link"   ? linkedFifo
                                                      : link;
            QTest::newRow(qPrintable(name + " into a " + kind))
                << kind << a << "special-" + kind + ".png" << reason;
        }
        ++w;
    }
    QTest::newRow("turntable frame 1 a FIFO")
        << "frames" << QStringList{"render", "--height", "h.png", "--turntable", "2",
                                   "--size", "16",       "--out", "spin.png"}
        << "spin-001.png" << fifo;
    QTest::newRow("export into a FIFO")
        << "fifo" << QStringList{"export", "--height", "h.png",           "--format",
                                 "gltf",   "--out",    "special-fifo.png"}
        << "special-fifo.png"
        << "exists and is not a folder";
    QTest::newRow("export into a link to a folder")
        << "dirlink"
        << QStringList{"export", "--height", "h.png", "--format", "gltf", "--out", "linked-dir"}
        << "linked-dir"
        << "is a symbolic link \\(to sub\\); an export replaces whole folders";
}

void FaultReachTest::specialFileAsOutput() {
    QFETCH(QString, kind);
    QFETCH(QStringList, args);
    QFETCH(QString, file);
    QFETCH(QString, reason);
    const QString path = m_dir + "/" + file;
    if (kind == "fifo") {
        QVERIFY(::mkfifo(path.toLocal8Bit().constData(), 0644) == 0);
    } else if (kind == "link") { // to a FIFO
        QVERIFY(::mkfifo(QString(m_dir + "/pipe-target").toLocal8Bit().constData(), 0644) == 0);
        QVERIFY(QFile::link("pipe-target", path));
    } else if (kind == "dangling") {
        QVERIFY(QFile::link("nowhere/none.png", path));
    } else if (kind == "socket") {
        const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        const QByteArray name = path.toLocal8Bit();
        QVERIFY(static_cast<std::size_t>(name.size()) < sizeof address.sun_path);
        std::memcpy(address.sun_path, name.constData(), static_cast<std::size_t>(name.size()));
        QVERIFY(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
        ::close(fd);
    } else if (kind == "dirlink") {
        QVERIFY(QFile::link("sub", path));
    } else if (kind == "frames") {
        QVERIFY(QFile::copy(m_dir + "/h.png", m_dir + "/spin-000.png"));
        QVERIFY(::mkfifo(path.toLocal8Bit().constData(), 0644) == 0);
    }
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, file, reason);
    QFile::remove(path);
    QFile::remove(m_dir + "/spin-000.png");
    QFile::remove(m_dir + "/pipe-target");
}

// A device as output: refused, never replaced by a regular file (as root, a rename would have
// replaced /dev/null itself).
void FaultReachTest::deviceAsOutput() {
    struct stat before {};
    QVERIFY(::stat("/dev/null", &before) == 0 && S_ISCHR(before.st_mode));
    for (const QStringList& args :
         {QStringList{"sample", "noise", "--size", "16", "--out", "/dev/null"},
          QStringList{"trace", "--height", "h.png", "--rays", "4", "--out", "/dev/null"}}) {
        PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, "/dev/null",
                                "is a character device, not a regular file: refusing to replace");
        struct stat after {};
        QVERIFY(::stat("/dev/null", &after) == 0 && S_ISCHR(after.st_mode));
        QCOMPARE(after.st_rdev, before.st_rdev);
    }
}

// An output named through a symbolic link to a regular file: the file is replaced, the link stays
// a link (never silently turned into a copy), nothing is left beside either.
void FaultReachTest::linkedOutputWrittenThrough() {
    QDir().mkpath(m_dir + "/shared");
    writeFile(m_dir + "/shared/out.png", "the previous picture");
    QVERIFY(QFile::link("shared/out.png", m_dir + "/linked.png"));
    const auto before = snapshot(m_dir);
    const CliRun run = runCli(m_dir, {"sample", "noise", "--size", "16", "--out", "linked.png"});
    QVERIFY2(run.status == 0, qPrintable(run.output));
    const auto after = snapshot(m_dir);
    QCOMPARE(after.value("linked.png"), before.value("linked.png")); // still the same link
    QVERIFY(after.value("shared/out.png").startsWith("\x89PNG"));
    QCOMPARE(QStringList(after.keys()), QStringList(before.keys()));
    QFile::remove(m_dir + "/linked.png");
    QDir(m_dir + "/shared").removeRecursively();
}

void FaultReachTest::specialFileAsInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("file");
    const QStringList render = {"render", "--size", "16", "--out", "r.png"};
    QTest::newRow("--height") << QStringList{"trace", "--height", "pipe.png", "--out", "t.csv"}
                              << "pipe.png";
    QTest::newRow("--material") << QStringList{"render", "--material", "pipe.json", "--out",
                                               "r.png"}
                                << "pipe.json";
    QTest::newRow("a material's map")
        << QStringList{"render", "--material", "piped.json", "--size", "16", "--out", "r.png"}
        << "pipe.png";
    QTest::newRow("--mesh") << QStringList{"render", "--height", "h.png", "--mesh", "pipe.obj",
                                           "--size", "16",       "--out", "r.png"}
                            << "pipe.obj";
    QTest::newRow("--environment")
        << QStringList{"render", "--height", "h.png", "--environment", "pipe.hdr",
                       "--size", "16",       "--out", "r.png"}
        << "pipe.hdr";
    QTest::newRow("a mesh's buffer")
        << QStringList{"render", "--height", "h.png", "--mesh", "meshes/piped.gltf",
                       "--size", "16",       "--out", "r.png"}
        << "pipe.bin";
    QTest::newRow("bench --from-csv")
        << QStringList{"bench", "--from-csv", "pipe.csv", "--plot", "p.svg"} << "pipe.csv";
}

// A FIFO (or any special file) to read is refused by name at once: never waited on.
void FaultReachTest::specialFileAsInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, file);
    for (const char* name :
         {"pipe.png", "pipe.json", "pipe.obj", "pipe.hdr", "pipe.csv", "meshes/pipe.bin"})
        QVERIFY(::mkfifo(QString(m_dir + "/" + name).toLocal8Bit().constData(), 0644) == 0);
    writeFile(m_dir + "/piped.json", R"({"format": "parallax-studio-material", "version": 1,
 "maps": {"height": "pipe.png"}})");
    writeFile(m_dir + "/meshes/piped.gltf", triangleGltf("pipe.bin"));
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, file,
                            "is a FIFO \\(named pipe\\), not a regular file; only regular files");
    for (const char* name : {"pipe.png", "pipe.json", "pipe.obj", "pipe.hdr", "pipe.csv",
                             "meshes/pipe.bin", "piped.json", "meshes/piped.gltf"})
        QFile::remove(m_dir + "/" + name);
}

// The issue's hang: a FIFO where the cone cache keeps a bake. recommend bakes instead, keeps
// the FIFO as it was (the cache write is refused, a note says why) and finishes.
void FaultReachTest::fifoInTheConeCacheDoesNotHang() {
    const QString cache = m_temp.path() + "/cache";
    QDir(cache).removeRecursively();
    QDir().mkpath(cache);
    const QStringList args = {"recommend", "--height",    "h.png", "--cache",
                              cache,       "--max-polar", "60"};
    QCOMPARE(runCli(m_dir, args).status, 0);
    const QStringList baked = QDir(cache).entryList({"cone-*.pxcone"});
    QVERIFY2(!baked.isEmpty(), qPrintable(QDir(cache).entryList().join(' ')));
    for (const QString& name : baked) {
        QVERIFY(QFile::remove(cache + "/" + name));
        QVERIFY(::mkfifo(QString(cache + "/" + name).toLocal8Bit().constData(), 0644) == 0);
    }
    const auto before = snapshot(cache);
    const CliRun run = runCli(m_dir, args);
    QVERIFY2(run.status == 0, qPrintable(run.output));
    QVERIFY2(run.seconds < 60.0, qPrintable(QString::number(run.seconds)));
    QCOMPARE(difference(before, snapshot(cache)), QString());
    record(run, true, false, 0);
}

// A cone map the cache holds is read like any other input: an output naming it is refused, and
// the entry stays as it was.
void FaultReachTest::coneCacheEntryIsAnInput() {
    const QString cache = m_dir + "/cones";
    QDir(cache).removeRecursively();
    const QStringList recommend = {"recommend",   "--height", "h.png",        "--cache", "cones",
                                   "--max-polar", "60",       "--techniques", "cone"};
    QCOMPARE(runCli(m_dir, recommend).status, 0);
    const QStringList baked = QDir(cache).entryList({"cone-*.pxcone"});
    QCOMPARE(baked.size(), 1);
    const QString entry = "cones/" + baked.front();
    const QStringList args = recommend + QStringList{"--out", entry};
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, entry,
                            "--out names the same file as [^\\n]*\\(a cached cone map\\), which "
                            "this run reads: refusing to overwrite an input");
    QDir(cache).removeRecursively();
}

// shader --dump-all writes every variant, whatever a material says, into a folder: a material
// beside it (whose maps could bear a variant's name) is a usage error, before anything is written.
void FaultReachTest::shaderDumpAllTakesNoMaterial() {
    writeFile(m_dir + "/pom.frag", "the artist's own shader\n");
    writeFile(m_dir + "/v.json", R"({"format": "parallax-studio-material", "version": 1,
 "maps": {"height": "h.png", "albedo": "pom.frag"}, "technique": {"name": "pom"}})");
    const QStringList args = {"shader", "--material", "v.json", "--dump-all", "."};
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 2, "--material",
                            "--(material|dump-all) excludes --(dump-all|material)");
    QFile::remove(m_dir + "/pom.frag");
    QFile::remove(m_dir + "/v.json");
}

void FaultReachTest::userFileNamedLikeALockKept_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("lock");
    QTest::addColumn<QByteArray>("bytes");
    QTest::newRow("export, notes")
        << QStringList{"export", "--height", "h.png", "--format", "gltf", "--out", "lockpkg"}
        << QString::fromStdString(px::temporaryName("lockpkg", "lock"))
        << QByteArray("the artist's notes\n");
    QTest::newRow("turntable, digits but no newline")
        << QStringList{"render", "--height", "h.png", "--turntable", "2",
                       "--size", "16",       "--out", "lspin.png"}
        << QString::fromStdString(px::temporaryName("lspin-000.png", "lock"))
        << QByteArray("20261126");
}

// A writer's lock (.px-lock-HASH, Temporaries.h) is the project's own file only when it holds what
// a writer puts there (a pid); a user's file of that name is refused, never truncated or removed.
void FaultReachTest::userFileNamedLikeALockKept() {
    QFETCH(QStringList, args);
    QFETCH(QString, lock);
    QFETCH(QByteArray, bytes);
    writeFile(m_dir + "/" + lock, bytes);
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, lock,
                            "is a file that Parallax Studio did not write; refusing to replace it");
    QFile::remove(m_dir + "/" + lock);
}

void FaultReachTest::meshReferencesStayInside_data() {
    QTest::addColumn<QString>("gltf");
    QTest::addColumn<QString>("reason");
    const QString outside = "refers to [^\\n]*, outside the folder";
    QTest::newRow("buffer ../../../../etc/passwd")
        << QString(triangleGltf("../../../../etc/passwd")) << "buffer 0 " + outside;
    QTest::newRow("buffer /etc/passwd")
        << QString(triangleGltf("/etc/passwd")) << "buffer 0 " + outside;
    QTest::newRow("buffer ../secret.txt, percent-escaped")
        << QString(triangleGltf("%2E%2E/secret.txt")) << "buffer 0 " + outside;
    QTest::newRow("buffer through a link to outside")
        << QString(triangleGltf("escape/secret.txt")) << "buffer 0 " + outside;
    QTest::newRow("buffer on the web") << QString(triangleGltf("http://example.com/tri.bin"))
                                       << "buffer 0 refers to http://example.com/tri.bin, which "
                                          "is not a file beside the mesh";
    QTest::newRow("image ../secret.txt")
        << QString(triangleGltf("tri.bin", R"(, "images": [{"uri": "../secret.txt"}])"))
        << "image 0 " + outside;
    QTest::newRow("OBJ material library ../outside.mtl")
        << "obj:mtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n"
        << "material library ../outside.mtl " + outside;
    QTest::newRow("OBJ texture ../secret.txt")
        << "obj:mtllib inner/lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n"
        << "texture ../../secret.txt of lib.mtl " + outside;
}

void FaultReachTest::meshReferencesStayInside() {
    QFETCH(QString, gltf);
    QFETCH(QString, reason);
    const QString folder = m_dir + "/meshes";
    QVERIFY(QFile::link(m_temp.path() + "/outside", folder + "/escape"));
    QDir().mkpath(m_temp.path() + "/outside");
    writeFile(m_temp.path() + "/outside/secret.txt", triangleBuffer());
    writeFile(m_dir + "/outside.mtl", "newmtl m\n");
    writeFile(folder + "/inner/lib.mtl", "newmtl m\nmap_Kd ../../secret.txt\n");
    const bool obj = gltf.startsWith("obj:");
    const QString name = obj ? "probe.obj" : "probe.gltf";
    writeFile(folder + "/" + name, obj ? gltf.mid(4).toUtf8() : gltf.toUtf8());
    PX_EXPECT_CLEAN_FAILURE(m_dir,
                            (QStringList{"render", "--height", "h.png", "--mesh", "meshes/" + name,
                                         "--size", "16", "--out", "r.png"}),
                            {}, 1, "meshes/" + name, reason);
    for (const QString& f : {folder + "/" + name, folder + "/escape", folder + "/inner/lib.mtl",
                             m_dir + "/outside.mtl"})
        QFile::remove(f);
}

void FaultReachTest::meshClaimsBeyondTheFile_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QByteArray>("buffer");
    QTest::addColumn<QString>("reason");
    const QByteArray tri = triangleBuffer();
    QTest::newRow("GLB: a 4 GiB JSON chunk in 792 bytes")
        << "claim.glb" << triangleGlb(0xFFFFFFF0u) << QByteArray()
        << "its JSON chunk claims 4294967280 bytes, past the end of the [0-9]+-byte file";
    QByteArray glb = triangleGlb(0);
    glb.replace(8, 4, little32(0x7FFFFFFFu));
    QTest::newRow("GLB: a header claiming 2 GiB")
        << "length.glb" << glb << QByteArray() << "its GLB header claims 2147483647 bytes";
    QTest::newRow("glTF: a buffer claiming 4 GB")
        << "long.gltf" << triangleGltf("long.bin", {}, "3", "4000000000") << tri
        << "buffer 0 claims 4000000000 bytes, but only 68 are there";
    QTest::newRow("glTF: an accessor of a billion vertices")
        << "count.gltf" << triangleGltf("count.bin", {}, "1000000000") << tri
        << "accessor 0 claims 1000000000 elements of 12 bytes, past the end of buffer view 0";
    QTest::newRow("glTF: a data: uri shorter than its byteLength")
        << "data.gltf" << triangleGltf("data:application/octet-stream;base64,AAAA") << QByteArray()
        << "buffer 0 claims 68 bytes, but only 3 are there";
    QTest::newRow("glTF: an index past the end")
        << "index.gltf" << triangleGltf("index.bin") << triangleBuffer(7)
        << "mesh 0 primitive 0: index 7 \\(at position 2\\) is past the end of its 3 vertices";
    QTest::newRow("glTF 1.0") << "old.gltf" << QByteArray(R"({"asset": {"version": "1.0"}})")
                              << QByteArray() << "it is glTF 1.0; the preview reads glTF 2.0";
    QByteArray faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
    for (int i = 0; i < 5000; ++i)
        faces += "f 1/1 2/1 3/1\n";
    QTest::newRow("OBJ: more triangles than the limit")
        << "many.obj" << faces << QByteArray()
        << "5000 triangles, more than the preview's limit of 1000";
}

// The file claims more than it holds, or more than the limit: refused before Assimp allocates
// (the process runs under an address-space limit that Assimp's allocations would exceed).
void FaultReachTest::meshClaimsBeyondTheFile() {
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    QFETCH(QByteArray, buffer);
    QFETCH(QString, reason);
    const QString folder = m_dir + "/meshes";
    writeFile(folder + "/" + name, bytes);
    const QString bin = QFileInfo(name).completeBaseName() + ".bin";
    if (!buffer.isEmpty())
        writeFile(folder + "/" + bin, buffer);
    const QStringList args = {
        "render", "--height", "h.png", "--mesh", "meshes/" + name, "--max-triangles",
        "1000",   "--size",   "16",    "--out",  "r.png"};
    const auto before = snapshot(m_dir);
    const CliRun run = runCli(m_dir, args, {}, kMeshMemory);
    QVERIFY2(run.status == 1, qPrintable(run.output));
    QVERIFY2(run.output.contains("error: meshes/" + name + ": "), qPrintable(run.output));
    QVERIFY2(run.output.contains(QRegularExpression(reason)), qPrintable(run.output));
    QCOMPARE(difference(before, snapshot(m_dir)), QString());
    record(run, true, run.signal != 0, 0);
    QFile::remove(folder + "/" + name);
    QFile::remove(folder + "/" + bin);
}

void FaultReachTest::exportNeverRemovesAnInput_data() {
    QTest::addColumn<QStringList>("first");
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("reason");
    const QString held = "holds [^ ]+, a file of the earlier export that this run reads";
    QTest::newRow("the material being exported, another format")
        << QStringList{"export", "--material", "m.json", "--format", "package", "--out", "pkg"}
        << QStringList{"export", "--material", "pkg/m.json", "--format",
                       "gltf",   "--out",      "pkg",        "--force"}
        << held;
    QTest::newRow("the material being exported, the same format")
        << QStringList{"export", "--material", "m.json", "--format", "package", "--out", "pkg"}
        << QStringList{"export",  "--material", "pkg/m.json", "--format",
                       "package", "--out",      "pkg",        "--force"}
        << held;
    QTest::newRow("its height map")
        << QStringList{"export", "--height", "h.png", "--format", "package", "--out", "pkg"}
        << QStringList{"export", "--height", "pkg/h_height.png", "--format", "godot",
                       "--out",  "pkg",      "--force"}
        << held;
    QTest::newRow("an albedo given on the command line")
        << QStringList{"export", "--material", "m.json", "--format", "package", "--out", "pkg"}
        << QStringList{"export",   "--height", "h.png", "--albedo", "pkg/m_albedo.png",
                       "--format", "gltf",     "--out", "pkg",      "--force"}
        << held;
}

// export --force removes and replaces only the files its earlier export listed, and never one
// the run reads: the material being exported or its maps lying in the output folder.
void FaultReachTest::exportNeverRemovesAnInput() {
    QFETCH(QStringList, first);
    QFETCH(QStringList, args);
    QFETCH(QString, reason);
    QDir(m_dir + "/pkg").removeRecursively();
    // The earlier export, made once for each way of making it and copied for the other cases.
    const QString earlierCopy =
        m_temp.path() + "/earlier-" + QString::number(qHash(first.join('\n')));
    if (QDir(earlierCopy).exists()) {
        QVERIFY(copyFolder(earlierCopy, m_dir + "/pkg"));
    } else {
        const CliRun earlier = runCli(m_dir, first);
        QVERIFY2(earlier.status == 0, qPrintable(earlier.output));
        QVERIFY(copyFolder(m_dir + "/pkg", earlierCopy));
    }
    PX_EXPECT_CLEAN_FAILURE(m_dir, args, {}, 1, "pkg", reason);
    QDir(m_dir + "/pkg").removeRecursively();
}

PX_FAULTS_MAIN(FaultReachTest)
#include "FaultReachTest.moc"

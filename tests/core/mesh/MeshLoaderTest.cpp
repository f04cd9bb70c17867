// Loading meshes: OBJ, glTF and GLB give the same mesh, a uv set can be chosen, and every bad
// mesh is a clear error naming the file (or, for degenerate triangles, a counted note).

#include "parallax/mesh/MeshLoader.h"

#include "TestMeshes.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <limits>

using namespace px;

class MeshLoaderTest : public QObject {
    Q_OBJECT

private slots:
    void init() { QVERIFY(m_dir.isValid()); }
    void formatsLoadAlike_data();
    void formatsLoadAlike();
    void fitsIntoTheUnitSphere();
    void chosenUvSetSetsTheDensity();
    void degenerateTrianglesAreDroppedAndCounted_data();
    void degenerateTrianglesAreDroppedAndCounted();
    void badMeshesAreClearErrors_data();
    void badMeshesAreClearErrors();
    void progressIsReportedAndCancels();

private:
    std::string path(const char* name) const { return m_dir.filePath(name).toStdString(); }
    QTemporaryDir m_dir;
};

void MeshLoaderTest::formatsLoadAlike_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("tangents");
    QTest::newRow("obj") << "torus.obj" << false;
    QTest::newRow("gltf") << "torus.gltf" << false;
    QTest::newRow("glb") << "torus.glb" << false;
    QTest::newRow("gltf with tangents") << "torus-tangents.gltf" << true;
}

void MeshLoaderTest::formatsLoadAlike() {
    QFETCH(QString, name);
    QFETCH(bool, tangents);
    const std::string file = path(name.toUtf8().constData());
    const test::TestMesh torus = test::torus(24, 12, tangents);
    QVERIFY(name.endsWith(".obj") ? test::writeObj(file, torus) : test::writeGltf(file, torus));
    Result<LoadedMesh> mesh = loadMesh(file);
    QVERIFY2(mesh.ok(), mesh.ok() ? "" : mesh.error().message.c_str());
    QCOMPARE(mesh->triangles, 24 * 12 * 2);
    QCOMPARE(mesh->uvSets, 1);
    QCOMPARE(mesh->fileTangents, tangents);
    QCOMPARE(mesh->droppedTriangles, 0);
    QCOMPARE(mesh->splitVertices, 0);
    // The seams keep their duplicated corners; the rest is shared: (24 + 1) x (12 + 1).
    QCOMPARE(static_cast<int>(mesh->mesh.vertices.size()), 25 * 13);
    // uv back in glTF's convention whatever the format: v = 1 - theta / 2pi lies in [0, 1] and
    // the outer equator (theta = 0, y = 0, farthest from the axis) has v = 1 or 0.
    for (const MeshVertex& v : mesh->mesh.vertices) {
        QVERIFY(v.uv.x >= 0.0f && v.uv.x <= 3.0f && v.uv.y >= 0.0f && v.uv.y <= 1.0f);
        const float fromAxis = std::hypot(v.position.x, v.position.z);
        if (fromAxis > 0.99f)
            QVERIFY2(v.uv.y < 1e-5f || v.uv.y > 1.0f - 1e-5f, qPrintable(QString::number(v.uv.y)));
    }
    QVERIFY(
        QString::fromStdString(mesh->summary()).contains(name + ": 576 triangles, uv set 0 of 1"));
}

// Centred and scaled uniformly: the torus (radius 1.4 around its centre) shrinks by 1 / 1.4
// and its tangents' lengths with it.
void MeshLoaderTest::fitsIntoTheUnitSphere() {
    const std::string file = path("far.obj");
    test::TestMesh torus = test::torus(24, 12, false);
    for (glm::vec3& p : torus.positions)
        p = p * 10.0f + glm::vec3(50.0f, -20.0f, 3.0f);
    QVERIFY(test::writeObj(file, torus));
    Result<LoadedMesh> mesh = loadMesh(file);
    QVERIFY(mesh.ok());
    QCOMPARE_LE(std::abs(mesh->fitScale - 1.0f / 14.0f), 1e-5f);
    float farthest = 0.0f;
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const MeshVertex& v : mesh->mesh.vertices) {
        farthest = std::max(farthest, glm::length(v.position));
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    QCOMPARE_LE(std::abs(farthest - 1.0f), 1e-5f);
    QCOMPARE_LE(glm::length(lo + hi), 1e-5f); // the bounding box's centre is the origin
}

// The second uv set repeats the texture twice as often: the loader reads it, and the frame's
// lengths (world units per uv unit, the depth scale) halve.
void MeshLoaderTest::chosenUvSetSetsTheDensity() {
    const std::string file = path("two-sets.glb");
    test::TestMesh torus = test::torus(24, 12, false);
    for (const glm::vec2& uv : torus.uvs)
        torus.uvs2.push_back(2.0f * uv);
    QVERIFY(test::writeGltf(file, torus));
    MeshLoadOptions second;
    second.uvSet = 1;
    Result<LoadedMesh> a = loadMesh(file), b = loadMesh(file, second);
    QVERIFY(a.ok() && b.ok());
    QCOMPARE(a->uvSets, 2);
    QCOMPARE(b->uvSet, 1);
    QVERIFY(QString::fromStdString(b->summary()).contains("uv set 1 of 2"));
    QCOMPARE(a->mesh.vertices.size(), b->mesh.vertices.size());
    for (std::size_t i = 0; i < a->mesh.vertices.size(); ++i) {
        const MeshVertex &va = a->mesh.vertices[i], &vb = b->mesh.vertices[i];
        QVERIFY(glm::length(vb.uv - 2.0f * va.uv) < 1e-5f);
        QVERIFY(std::abs(glm::length(vb.tangent) - 0.5f * glm::length(va.tangent)) <
                1e-4f * glm::length(va.tangent));
        QVERIFY(std::abs(glm::length(vb.bitangent) - 0.5f * glm::length(va.bitangent)) <
                1e-4f * glm::length(va.bitangent));
    }
}

void MeshLoaderTest::degenerateTrianglesAreDroppedAndCounted_data() {
    QTest::addColumn<QString>("name");
    QTest::newRow("obj") << "degenerate.obj";
    QTest::newRow("gltf") << "degenerate.gltf";
}

void MeshLoaderTest::degenerateTrianglesAreDroppedAndCounted() {
    QFETCH(QString, name);
    const std::string file = path(name.toUtf8().constData());
    const test::TestMesh mesh = test::withDegenerateTriangles(test::torus(12, 6, false));
    QVERIFY(name.endsWith(".obj") ? test::writeObj(file, mesh) : test::writeGltf(file, mesh));
    Result<LoadedMesh> loaded = loadMesh(file);
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
    QCOMPARE(loaded->droppedTriangles, 3);
    QCOMPARE(loaded->triangles, 12 * 6 * 2);
    QCOMPARE(loaded->notes.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(loaded->notes[0]),
             QString::fromStdString(file) + ": dropped 3 of 147 triangles with zero area in "
                                            "position or uv");
    for (const MeshVertex& v : loaded->mesh.vertices)
        QVERIFY(std::isfinite(glm::length(v.tangent)) && std::isfinite(glm::length(v.bitangent)));
}

void MeshLoaderTest::badMeshesAreClearErrors_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("expected"); // after "FILE: "
    QTest::newRow("missing") << "missing.obj"
                             << "no such file";
    QTest::newRow("not a mesh") << "notes.txt"
                                << "not a mesh file";
    QTest::newRow("no uv obj") << "no-uv.obj"
                               << "has no texture coordinates \\(uv\\)";
    QTest::newRow("no uv glb") << "no-uv.glb"
                               << "has no texture coordinates \\(uv\\)";
    QTest::newRow("nan obj") << "nan.obj"
                             << "vertex [0-9]+ of mesh";
    QTest::newRow("nan glb") << "nan.glb"
                             << "vertex [0-9]+ of mesh";
    QTest::newRow("uv set") << "one-set.gltf"
                            << "has 1 uv set; uv set 1 does not exist";
    QTest::newRow("too many") << "big.obj"
                              << "288 triangles, more than the preview's limit of 100";
    QTest::newRow("all degenerate") << "flat.obj"
                                    << "every one of its 2 triangles is degenerate";
    QTest::newRow("garbage glb") << "garbage.glb"
                                 << "cannot read it as a mesh";
    QTest::newRow("empty obj") << "empty.obj"
                               << "cannot read it as a mesh";
}

void MeshLoaderTest::badMeshesAreClearErrors() {
    QFETCH(QString, name);
    QFETCH(QString, expected);
    const std::string file = path(name.toUtf8().constData());
    test::TestMesh torus = test::torus(12, 12, false);
    MeshLoadOptions options;
    if (name == "notes.txt" || name == "garbage.glb") {
        std::ofstream(file) << "glTF but not really, nor an OBJ\n";
    } else if (name == "empty.obj") {
        std::ofstream(file) << "";
    } else if (name.startsWith("no-uv")) {
        torus.uvs.clear();
        QVERIFY(name.endsWith(".obj") ? test::writeObj(file, torus) : test::writeGltf(file, torus));
    } else if (name.startsWith("nan")) {
        torus.positions[5].y = std::numeric_limits<float>::quiet_NaN();
        QVERIFY(name.endsWith(".obj") ? test::writeObj(file, torus) : test::writeGltf(file, torus));
        expected += ".*non-finite position";
    } else if (name == "one-set.gltf") {
        QVERIFY(test::writeGltf(file, torus));
        options.uvSet = 1;
    } else if (name == "big.obj") {
        QVERIFY(test::writeObj(file, torus));
        options.maxTriangles = 100;
    } else if (name == "flat.obj") {
        test::TestMesh flat;
        flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
        flat.normals.assign(4, {0, 0, 1});
        flat.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
        flat.indices = {0, 1, 2, 0, 0, 3};
        QVERIFY(test::writeObj(file, flat));
    }
    Result<LoadedMesh> mesh = loadMesh(file, options);
    QVERIFY(!mesh.ok());
    const QString message = QString::fromStdString(mesh.error().message);
    QVERIFY2(message.startsWith(QString::fromStdString(file) + ": "), qPrintable(message));
    QVERIFY2(message.contains(QRegularExpression(expected)), qPrintable(message));
    QCOMPARE(mesh.error().file, file);
}

void MeshLoaderTest::progressIsReportedAndCancels() {
    const std::string file = path("progress.obj");
    QVERIFY(test::writeObj(file, test::torus(48, 24, false)));
    std::vector<float> reports;
    MeshLoadOptions watch;
    watch.progress = [&](float f) {
        reports.push_back(f);
        return true;
    };
    QVERIFY(loadMesh(file, watch).ok());
    QVERIFY(!reports.empty());
    for (float f : reports)
        QVERIFY(f >= 0.0f && f <= 1.0f);
    MeshLoadOptions cancel;
    cancel.progress = [](float) { return false; };
    Result<LoadedMesh> cancelled = loadMesh(file, cancel);
    QVERIFY(!cancelled.ok());
    QVERIFY(cancelled.error().cancelled());
}

QTEST_APPLESS_MAIN(MeshLoaderTest)
#include "MeshLoaderTest.moc"

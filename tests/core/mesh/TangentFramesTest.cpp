// Tangent frames of loaded meshes: the generated ones equal an independent MikkTSpace-style
// computation (written here in double precision from Mikkelsen's description: per corner,
// dP/du projected on the tangent plane and weighted by the corner angle, summed per vertex and uv
// orientation) and Blender's MikkTSpace on the same meshes, and follow the analytic surface;
// mirrored uv splits vertices; a file's own tangents are kept.

#include "parallax/mesh/TangentFrames.h"

#include "TestMeshes.h"
#include "parallax/mesh/MeshLoader.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <glm/geometric.hpp>

using namespace px;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Reference {
    glm::dvec3 tangent{0.0};
    double lengthU = 0.0, lengthV = 0.0, weight = 0.0;
    int positive = 0, negative = 0; // corners by the sign of their triangle's uv area
};

glm::dvec3 onPlane(glm::dvec3 v, glm::dvec3 n) {
    return v - n * glm::dot(n, v);
}

// Mikkelsen's per-triangle vectors: vOs = t31.y d21 - t21.y d31 and vOt = -t31.x d21 + t21.x
// d31, scaled by 1 / (signed uv area): dP/du and dP/dv.
std::vector<Reference> reference(const MeshData& mesh) {
    std::vector<Reference> out(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        for (int k = 0; k < 3; ++k) {
            const MeshVertex& v0 = mesh.vertices[mesh.indices[i + k]];
            const MeshVertex& v1 = mesh.vertices[mesh.indices[i + (k + 1) % 3]];
            const MeshVertex& v2 = mesh.vertices[mesh.indices[i + (k + 2) % 3]];
            const glm::dvec3 d21 = glm::dvec3(v1.position) - glm::dvec3(v0.position);
            const glm::dvec3 d31 = glm::dvec3(v2.position) - glm::dvec3(v0.position);
            const glm::dvec2 t21 = glm::dvec2(v1.uv) - glm::dvec2(v0.uv);
            const glm::dvec2 t31 = glm::dvec2(v2.uv) - glm::dvec2(v0.uv);
            const double area = t21.x * t31.y - t21.y * t31.x;
            const glm::dvec3 os = (t31.y * d21 - t21.y * d31) / area;
            const glm::dvec3 ot = (-t31.x * d21 + t21.x * d31) / area;
            const glm::dvec3 n = glm::normalize(glm::dvec3(v0.normal));
            const double angle = std::acos(std::clamp(
                glm::dot(glm::normalize(onPlane(d21, n)), glm::normalize(onPlane(d31, n))), -1.0,
                1.0));
            Reference& r = out[mesh.indices[i + k]];
            r.tangent += angle * glm::normalize(onPlane(os, n));
            r.lengthU += angle * glm::length(onPlane(os, n));
            r.lengthV += angle * glm::length(onPlane(ot, n));
            r.weight += angle;
            (area > 0.0 ? r.positive : r.negative) += 1;
        }
    }
    return out;
}

double angleDeg(glm::dvec3 a, glm::dvec3 b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) *
           180.0 / kPi;
}

} // namespace

class TangentFramesTest : public QObject {
    Q_OBJECT

private slots:
    void init() { QVERIFY(m_dir.isValid()); }
    void generatedFramesMatchMikkTSpace_data();
    void generatedFramesMatchMikkTSpace();
    void generatedFramesMatchBlendersMikkTSpace_data();
    void generatedFramesMatchBlendersMikkTSpace();
    void framesFollowTheSurface_data();
    void framesFollowTheSurface();
    void mirroredUvSplitsVertices();
    void fileTangentsAreKept();
    void fileTangentsFollowANodeScale_data();
    void fileTangentsFollowANodeScale();
    void handednessIsGltfs();
    void depthScaleFollowsUvDensity();

private:
    std::string write(const char* name, const test::TestMesh& mesh) const {
        const std::string file = m_dir.filePath(name).toStdString();
        const bool ok = QString(name).endsWith(".obj") ? test::writeObj(file, mesh)
                                                       : test::writeGltf(file, mesh);
        return ok ? file : std::string();
    }
    QTemporaryDir m_dir;
};

void TangentFramesTest::generatedFramesMatchMikkTSpace_data() {
    QTest::addColumn<QString>("name");
    QTest::newRow("torus obj") << "torus.obj";
    QTest::newRow("torus gltf") << "torus.gltf";
    QTest::newRow("seamed sphere glb") << "sphere.glb";
    QTest::newRow("mirrored sphere obj") << "mirrored.obj";
    QTest::newRow("scaled sphere gltf") << "scaled.gltf";
}

static test::TestMesh meshNamed(const QString& name) {
    if (name.startsWith("torus"))
        return test::torus(32, 16, false);
    if (name.startsWith("mirrored"))
        return test::mirroredSphere(32, 16);
    if (name.startsWith("scaled"))
        return test::scaled(test::seamedSphere(32, 16), {1.6f, 1.0f, 0.6f});
    return test::seamedSphere(32, 16);
}

// Every vertex's frame against the reference: the tangent's direction, B on the side of its
// triangles' uv orientation (after splitting, one orientation per vertex), the lengths.
void TangentFramesTest::generatedFramesMatchMikkTSpace() {
    QFETCH(QString, name);
    const std::string file = write(name.toUtf8().constData(), meshNamed(name));
    QVERIFY(!file.empty());
    Result<LoadedMesh> loaded = loadMesh(file);
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
    QVERIFY(!loaded->fileTangents);
    const MeshData& mesh = loaded->mesh;
    const std::vector<Reference> ref = reference(mesh);
    double worstAngle = 0.0, worstLength = 0.0;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Reference& r = ref[i];
        if (r.weight == 0.0)
            continue;
        QVERIFY2(r.positive == 0 || r.negative == 0,
                 qPrintable(QString("vertex %1 serves both uv orientations").arg(i)));
        const MeshVertex& v = mesh.vertices[i];
        const glm::dvec3 n = glm::normalize(glm::dvec3(v.normal));
        const glm::dvec3 t = glm::normalize(onPlane(r.tangent, n));
        worstAngle = std::max(worstAngle, angleDeg(glm::dvec3(v.tangent), t));
        const double side = r.positive > 0 ? 1.0 : -1.0; // dP/dv's side of N x T
        QVERIFY(glm::dot(glm::dvec3(v.bitangent), side * glm::cross(n, t)) > 0.0);
        QVERIFY(angleDeg(glm::dvec3(v.bitangent), side * glm::cross(n, t)) < 0.01);
        worstLength =
            std::max({worstLength, std::abs(glm::length(v.tangent) / (r.lengthU / r.weight) - 1.0),
                      std::abs(glm::length(v.bitangent) / (r.lengthV / r.weight) - 1.0)});
    }
    QVERIFY2(
        worstAngle < 0.01 && worstLength < 1e-4,
        qPrintable(
            QString("worst tangent %1 deg, worst length %2").arg(worstAngle).arg(worstLength)));
}

void TangentFramesTest::generatedFramesMatchBlendersMikkTSpace_data() {
    QTest::addColumn<QString>("name");
    for (const char* name :
         {"uv-sphere", "torus", "suzanne", "suzanne-mirrored", "cube-flat", "grid-bumpy"})
        QTest::newRow(name) << name;
}

// Against an independent implementation: Blender's MikkTSpace (mesh.calc_tangents), whose
// tangents its glTF exporter wrote into these files with the very vertices they belong to
// (tests/data/mikktspace/make-blender-tangents.py). The frames generated here from the same
// positions, normals and uv have the same tangent directions and the same handedness w, corner by
// corner, mirrored halves and flat shading included.
void TangentFramesTest::generatedFramesMatchBlendersMikkTSpace() {
    QFETCH(QString, name);
    const std::string file = std::string(PX_MIKKTSPACE_DIR) + "/" + name.toStdString() + ".glb";
    Result<LoadedMesh> loaded = loadMesh(file);
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
    QVERIFY(loaded->fileTangents);
    QCOMPARE(loaded->droppedTriangles, 0);
    const MeshData& blender = loaded->mesh;
    MeshData ours = blender;
    generateTangentFrames(ours);
    QCOMPARE(ours.indices.size(), blender.indices.size());
    double worst = 0.0;
    int mirrored = 0;
    for (std::size_t c = 0; c < blender.indices.size(); ++c) {
        const MeshVertex& theirs = blender.vertices[blender.indices[c]];
        const MeshVertex& mine = ours.vertices[ours.indices[c]];
        QVERIFY(glm::length(theirs.position - mine.position) == 0.0f);
        worst = std::max(worst, angleDeg(glm::dvec3(mine.tangent), glm::dvec3(theirs.tangent)));
        QVERIFY2(gltfHandedness(mine) == gltfHandedness(theirs),
                 qPrintable(QString("corner %1: w %2, Blender's %3")
                                .arg(c)
                                .arg(gltfHandedness(mine))
                                .arg(gltfHandedness(theirs))));
        mirrored += gltfHandedness(theirs) < 0.0f ? 1 : 0;
    }
    qInfo("%s: %zu corners, %d of them mirrored; tangents within %.4f deg of Blender's",
          qPrintable(name), blender.indices.size(), mirrored, worst);
    QVERIFY2(worst < 0.05, qPrintable(QString("%1 deg").arg(worst)));
    // The mirrored model: its left half (the mirror shares the right half's uv).
    if (name.contains("mirrored"))
        QVERIFY(mirrored * 5 > static_cast<int>(blender.indices.size()) * 2);
}

void TangentFramesTest::framesFollowTheSurface_data() {
    QTest::addColumn<QString>("name");
    QTest::newRow("torus") << "torus.obj";
    QTest::newRow("seamed sphere") << "sphere.glb";
    QTest::newRow("scaled sphere") << "scaled.gltf";
}

// Against the analytic dP/du and dP/dv of the generated surface (scaled by the loader's fit): the
// tessellation's chords differ from the tangent by about half a segment's turn.
void TangentFramesTest::framesFollowTheSurface() {
    QFETCH(QString, name);
    const test::TestMesh source = meshNamed(name);
    const std::string file = write(name.toUtf8().constData(), source);
    Result<LoadedMesh> loaded = loadMesh(file);
    QVERIFY(loaded.ok());
    // The fit (MeshLoader.h): bounding box centre to the origin, then the scale.
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& p : source.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    struct Worst {
        double tangent = 0.0, bitangent = 0.0, length = 0.0;
    } inside, seamWorst;
    int compared = 0;
    for (const MeshVertex& v : loaded->mesh.vertices) {
        // The source vertex with this position and uv.
        std::size_t k = 0;
        while (
            k < source.positions.size() &&
            (glm::length((source.positions[k] - centre) * loaded->fitScale - v.position) > 1e-4f ||
             glm::length(source.uvs[k] - v.uv) > 1e-5f))
            ++k;
        QVERIFY2(k < source.positions.size(), "a loaded vertex the source does not have");
        // The sphere's polar caps (within 30 degrees of a pole): dP/du shrinks to nothing there.
        if (!name.startsWith("torus") && (v.uv.y < 1.0f / 6.0f || v.uv.y > 5.0f / 6.0f))
            continue;
        // On a seam a vertex sees the triangles of one side only: a one-sided difference.
        const bool seam = v.uv.x == 0.0f || v.uv.x == source.uvs.back().x;
        const glm::dvec3 du = glm::dvec3(source.dPdu[k]) * double(loaded->fitScale);
        const glm::dvec3 dv = glm::dvec3(source.dPdv[k]) * double(loaded->fitScale);
        const glm::dvec3 n = glm::normalize(glm::dvec3(v.normal));
        Worst& worst = seam ? seamWorst : inside;
        worst.tangent = std::max(worst.tangent, angleDeg(glm::dvec3(v.tangent), onPlane(du, n)));
        // B is N x T, dP/dv need not be perpendicular to dP/du (the scaled sphere): compare
        // sides and the projected length.
        QVERIFY(glm::dot(glm::dvec3(v.bitangent), dv) > 0.0);
        worst.bitangent =
            std::max(worst.bitangent, angleDeg(glm::dvec3(v.bitangent),
                                               onPlane(dv, glm::normalize(glm::dvec3(v.tangent)))));
        const double lengthError = std::max(
            std::abs(glm::length(glm::dvec3(v.tangent)) / glm::length(onPlane(du, n)) - 1.0),
            std::abs(glm::length(glm::dvec3(v.bitangent)) / glm::length(onPlane(dv, n)) - 1.0));
        worst.length = std::max(worst.length, lengthError);
        ++compared;
    }
    QVERIFY(compared > 100);
    for (const auto& [worst, where] :
         {std::pair{inside, "inside"}, std::pair{seamWorst, "on the seam"}})
        qInfo("%s %s: tangent within %.3f deg, bitangent within %.3f deg, lengths within %.2f%%",
              qPrintable(name), where, worst.tangent, worst.bitangent, 100.0 * worst.length);
    // Inside, the corners around a vertex balance their chords' errors; a seam's one side cannot.
    // B = N x T is perpendicular to T, which dP/dv is not on the scaled sphere.
    const bool orthogonal = !name.startsWith("scaled");
    // The torus's 16-segment tube: chords tilt 11.25 degrees out of a vertex's tangent plane, so
    // their projected lengths are cos 11.25 = 0.981 of the arc's, times the chord's 0.994.
    QVERIFY(inside.tangent < 1.5 && inside.length < 0.03);
    QVERIFY(!orthogonal || inside.bitangent < 0.01);
    QVERIFY(seamWorst.tangent < 6.0 && seamWorst.length < 0.1);
}

void TangentFramesTest::mirroredUvSplitsVertices() {
    Result<LoadedMesh> mirrored = loadMesh(write("mirrored.obj", test::mirroredSphere(32, 16)));
    Result<LoadedMesh> seamed = loadMesh(write("seamed.obj", test::seamedSphere(32, 16)));
    QVERIFY(mirrored.ok() && seamed.ok());
    QCOMPARE(mirrored->splitVertices, 2 * 17);
    QCOMPARE(seamed->splitVertices, 0);
    QVERIFY(QString::fromStdString(mirrored->summary()).contains("34 vertices split"));
}

// The file's tangents turned 20 degrees from dP/du: the loaded frame keeps them (and does not
// equal the generated one), with the uv density's lengths.
void TangentFramesTest::fileTangentsAreKept() {
    const test::TestMesh withTangents = test::torus(32, 16, true, 20.0f);
    Result<LoadedMesh> kept = loadMesh(write("kept.gltf", withTangents));
    Result<LoadedMesh> generated = loadMesh(write("generated.gltf", test::torus(32, 16, false)));
    QVERIFY(kept.ok() && generated.ok());
    QVERIFY(kept->fileTangents);
    QCOMPARE(kept->mesh.vertices.size(), generated->mesh.vertices.size());
    double worstKept = 0.0, leastGenerated = 180.0;
    for (std::size_t i = 0; i < kept->mesh.vertices.size(); ++i) {
        const MeshVertex &a = kept->mesh.vertices[i], &b = generated->mesh.vertices[i];
        // The same vertex in both (the loader keeps the file's order).
        QVERIFY(glm::length(a.position - b.position) < 1e-5f);
        std::size_t k = 0;
        while (k < withTangents.uvs.size() &&
               (glm::length(withTangents.uvs[k] - a.uv) > 1e-5f ||
                glm::length(withTangents.normals[k] - a.normal) > 1e-4f))
            ++k;
        QVERIFY(k < withTangents.uvs.size());
        worstKept = std::max(worstKept, angleDeg(glm::dvec3(a.tangent),
                                                 glm::dvec3(glm::vec3(withTangents.tangents[k]))));
        leastGenerated =
            std::min(leastGenerated, angleDeg(glm::dvec3(a.tangent), glm::dvec3(b.tangent)));
        QVERIFY(std::abs(glm::length(a.tangent) / glm::length(b.tangent) - 1.0f) < 1e-4f);
        // w = +1: B = dP/dv points down the image, as the generated frame's.
        QVERIFY(glm::dot(a.bitangent, b.bitangent) > 0.0f);
    }
    QVERIFY2(worstKept < 0.01, qPrintable(QString::number(worstKept)));
    // Turned 20 degrees; the generated ones differ from dP/du by up to 5.6
    // (framesFollowTheSurface).
    QVERIFY2(leastGenerated > 14.0, qPrintable(QString::number(leastGenerated)));
}

void TangentFramesTest::fileTangentsFollowANodeScale_data() {
    QTest::addColumn<float>("x");
    QTest::newRow("scale (1.6, 1, 0.6)") << 1.6f;
    QTest::newRow("mirroring scale (-1.6, 1, 0.6)") << -1.6f;
}

// A glTF node scaling non-uniformly over a torus with its own tangents (turned 20 degrees from
// dP/du): a tangent is a direction along the surface, so it goes by the scale S itself (the
// normal by S^-1) and reads as it does with the scale baked into the vertices (TestMeshes'
// `scaled`), lengths included; B stays on dP/dv's side. A mirroring scale turns the triangles
// over (they still wind counter-clockwise from outside) and the handedness with them.
void TangentFramesTest::fileTangentsFollowANodeScale() {
    QFETCH(float, x);
    const glm::vec3 scale(x, 1.0f, 0.6f);
    test::TestMesh node = test::torus(32, 16, true, 20.0f);
    node.nodeScale = scale;
    const test::TestMesh baked = test::scaled(test::torus(32, 16, true, 20.0f), scale);
    Result<LoadedMesh> a = loadMesh(write("node-scale.gltf", node));
    Result<LoadedMesh> b = loadMesh(write("baked-scale.gltf", baked));
    QVERIFY2(a.ok(), a.ok() ? "" : a.error().message.c_str());
    QVERIFY(b.ok() && a->fileTangents && b->fileTangents);
    QCOMPARE(a->mesh.vertices.size(), b->mesh.vertices.size());
    double worstAngle = 0.0, worstSource = 0.0, worstLength = 0.0;
    for (std::size_t i = 0; i < a->mesh.vertices.size(); ++i) {
        const MeshVertex &v = a->mesh.vertices[i], &w = b->mesh.vertices[i];
        QVERIFY(glm::length(v.position - w.position) < 1e-5f);
        QVERIFY(angleDeg(glm::dvec3(v.normal), glm::dvec3(w.normal)) < 0.01);
        worstAngle = std::max(worstAngle, angleDeg(glm::dvec3(v.tangent), glm::dvec3(w.tangent)));
        worstLength = std::max(
            {worstLength, std::abs(double(glm::length(v.tangent) / glm::length(w.tangent)) - 1.0),
             std::abs(double(glm::length(v.bitangent) / glm::length(w.bitangent)) - 1.0)});
        // And against S t from the file, directly; B on the side of the scaled dP/dv.
        std::size_t k = 0;
        while (k < baked.uvs.size() && (glm::length(baked.uvs[k] - v.uv) > 1e-5f ||
                                        glm::length(baked.normals[k] - v.normal) > 1e-4f))
            ++k;
        QVERIFY(k < baked.uvs.size());
        worstSource = std::max(
            worstSource, angleDeg(glm::dvec3(v.tangent), glm::dvec3(glm::vec3(baked.tangents[k]))));
        QVERIFY(glm::dot(v.bitangent, baked.dPdv[k]) > 0.0f);
        QCOMPARE(gltfHandedness(v), x > 0.0f ? 1.0f : -1.0f);
    }
    const MeshData& mesh = a->mesh;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const MeshVertex& p = mesh.vertices[mesh.indices[t]];
        const MeshVertex& q = mesh.vertices[mesh.indices[t + 1]];
        const MeshVertex& r = mesh.vertices[mesh.indices[t + 2]];
        QVERIFY(glm::dot(glm::cross(q.position - p.position, r.position - p.position),
                         p.normal + q.normal + r.normal) > 0.0f);
    }
    qInfo("node scale against baked: tangents within %.4f deg, lengths within %.2g; against S t "
          "within %.4f deg",
          worstAngle, worstLength, worstSource);
    QVERIFY2(worstAngle < 0.01 && worstSource < 0.01 && worstLength < 1e-4,
             qPrintable(
                 QString("%1 deg, %2 deg, %3").arg(worstAngle).arg(worstSource).arg(worstLength)));
}

// glTF's w: +1 on the unmirrored torus; on the mirrored sphere, +1 on one half and -1 on the
// other.
void TangentFramesTest::handednessIsGltfs() {
    Result<LoadedMesh> torus = loadMesh(write("w.obj", test::torus(16, 8, false)));
    QVERIFY(torus.ok());
    for (const MeshVertex& v : torus->mesh.vertices)
        QCOMPARE(gltfHandedness(v), 1.0f);
    Result<LoadedMesh> mirrored = loadMesh(write("wm.obj", test::mirroredSphere(16, 8)));
    QVERIFY(mirrored.ok());
    int plus = 0, minus = 0;
    for (const MeshVertex& v : mirrored->mesh.vertices)
        (gltfHandedness(v) > 0.0f ? plus : minus) += 1;
    QVERIFY(plus > 0 && minus > 0);
}

// Three unit squares in a row, the middle one's uv squeezed to half a tile across: the left square
// shares no vertex with it (a uv seam), the right one shares its edge. Lw = sqrt(|T| |B|), the
// depth scale in world units per uv unit, is each triangle's own sqrt(world area / uv area) where
// its vertices serve only it, and the angle-weighted mean of both sides on a shared edge.
void TangentFramesTest::depthScaleFollowsUvDensity() {
    MeshData m;
    auto quad = [&](float x0, float u0, float uWidth) {
        const unsigned base = static_cast<unsigned>(m.vertices.size());
        for (int j = 0; j <= 1; ++j) {
            for (int i = 0; i <= 1; ++i)
                m.vertices.push_back({{x0 + static_cast<float>(i), 0.0f, static_cast<float>(j)},
                                      {0.0f, 1.0f, 0.0f},
                                      {u0 + uWidth * static_cast<float>(i), static_cast<float>(j)},
                                      {},
                                      {}});
        }
        // Counter-clockwise seen from +y: (x, z) = (0,0), (0,1), (1,0).
        const unsigned a = base, b = base + 1, c = base + 2, d = base + 3;
        m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    };
    quad(0.0f, 0.0f, 1.0f); // vertices 0-3, density 1 x 1
    quad(1.0f, 1.0f, 0.5f); // 4-7: |dP/du| = 2, |dP/dv| = 1
    quad(2.0f, 1.5f, 1.0f); // 8-11
    // Weld the right square's left edge to the middle one's right edge.
    for (unsigned& i : m.indices) {
        if (i == 8)
            i = 5;
        else if (i == 10)
            i = 7;
    }
    QCOMPARE(generateTangentFrames(m), 0);
    auto Lw = [&](unsigned v) {
        return std::sqrt(glm::length(m.vertices[v].tangent) * glm::length(m.vertices[v].bitangent));
    };
    for (unsigned v : {0u, 1u, 2u, 3u})
        QCOMPARE_LE(std::abs(Lw(v) - 1.0f), 1e-6f);
    for (unsigned v : {4u, 6u})
        QCOMPARE_LE(std::abs(Lw(v) - std::sqrt(2.0f)), 1e-6f);
    // Vertex 5 (x = 2, z = 0): 90 degrees of corners in each square, so |dP/du| = (2 + 1) / 2.
    QCOMPARE_LE(std::abs(glm::length(m.vertices[5].tangent) - 1.5f), 1e-5f);
    QCOMPARE_LE(std::abs(glm::length(m.vertices[5].bitangent) - 1.0f), 1e-5f);
    for (unsigned v : {9u, 11u})
        QCOMPARE_LE(std::abs(Lw(v) - 1.0f), 1e-6f);
}

QTEST_APPLESS_MAIN(TangentFramesTest)
#include "TangentFramesTest.moc"

// The preview meshes (no GL needed): the tangent frame is the surface's dP/du and dP/dv,
// normals point outwards, triangles wind counter-clockwise seen from outside. And the camera's
// angle conventions.

#include "parallax/render/Mesh.h"

#include "parallax/render/Camera.h"

#include <QtTest>
#include <glm/geometric.hpp>

using namespace px;

class MeshTest : public QObject {
    Q_OBJECT

private slots:
    void framesAreSurfaceDerivatives_data();
    void framesAreSurfaceDerivatives();
    void anglesFollowTheConvention();
    void namesRoundTrip();
};

void MeshTest::framesAreSurfaceDerivatives_data() {
    QTest::addColumn<int>("kind");
    for (std::size_t i = 0; i < meshKindNames().size(); ++i)
        QTest::newRow(meshKindNames()[i].data()) << static_cast<int>(i);
}

// For each triangle, dP/du and dP/dv solved from its corners must match the vertices' T and B
// (exactly on flat faces, to the tessellation's accuracy on curved ones); its geometric normal
// must agree with the vertex normals and point away from the centre.
void MeshTest::framesAreSurfaceDerivatives() {
    QFETCH(int, kind);
    const MeshData mesh = makeMesh(static_cast<MeshKind>(kind));
    QVERIFY(!mesh.indices.empty() && mesh.indices.size() % 3 == 0);
    int checked = 0;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const MeshVertex& a = mesh.vertices[mesh.indices[i]];
        const MeshVertex& b = mesh.vertices[mesh.indices[i + 1]];
        const MeshVertex& c = mesh.vertices[mesh.indices[i + 2]];
        const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
        const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
        const float det = d1.x * d2.y - d2.x * d1.y;
        QVERIFY(std::abs(det) > 1e-12f);
        const glm::vec3 T = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 B = (e2 * d1.x - e1 * d2.x) / det;
        const glm::vec3 vertexT = (a.tangent + b.tangent + c.tangent) / 3.0f;
        const glm::vec3 vertexB = (a.bitangent + b.bitangent + c.bitangent) / 3.0f;
        const glm::vec3 geometric = glm::cross(e1, e2);
        const glm::vec3 normal = a.normal + b.normal + c.normal;
        const glm::vec3 centre = (a.position + b.position + c.position) / 3.0f;
        QVERIFY2(glm::dot(geometric, normal) > 0.0f,
                 qPrintable(QString("triangle %1 winds clockwise").arg(i / 3)));
        // Closed meshes around the origin face away from it; the plane faces up.
        const glm::vec3 outwards =
            kind == static_cast<int>(MeshKind::Plane) ? glm::vec3(0, 1, 0) : centre;
        QVERIFY2(glm::dot(normal, outwards) > 0.0f,
                 qPrintable(QString("triangle %1 faces inwards").arg(i / 3)));
        // Skip the sphere's polar caps, where |T| changes fast from row to row.
        if (glm::length(vertexT) < 0.4f * glm::length(vertexB))
            continue;
        // Flat faces: exact. Curved: the chord of a 64-segment tessellation against the vertex
        // frames, which vary across the triangle.
        const bool flat =
            kind == static_cast<int>(MeshKind::Plane) || kind == static_cast<int>(MeshKind::Cube);
        const float tolerance = flat ? 1e-5f : 0.1f;
        QVERIFY2(
            glm::length(T - vertexT) <= tolerance * glm::length(vertexT) + 1e-5f,
            qPrintable(
                QString("triangle %1: dP/du off by %2").arg(i / 3).arg(glm::length(T - vertexT))));
        QVERIFY2(
            glm::length(B - vertexB) <= tolerance * glm::length(vertexB) + 1e-5f,
            qPrintable(
                QString("triangle %1: dP/dv off by %2").arg(i / 3).arg(glm::length(B - vertexB))));
        ++checked;
    }
    QVERIFY(checked > 0);
}

void MeshTest::anglesFollowTheConvention() {
    auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-5f; };
    QVERIFY(near(directionFromAngles(0, 0), {0, 0, 1}));
    QVERIFY(near(directionFromAngles(90, 0), {1, 0, 0}));
    QVERIFY(near(directionFromAngles(0, 90), {0, 1, 0}));
    OrbitCamera camera;
    camera.azimuthDeg = 0;
    camera.elevationDeg = 0;
    camera.distance = 5;
    QVERIFY(near(camera.position(), {0, 0, 5}));
    // The view looks at the target: the origin lands in the middle of the image.
    const glm::vec4 clip = camera.projection(1.0f) * camera.view() * glm::vec4(0, 0, 0, 1);
    QVERIFY(std::abs(clip.x / clip.w) < 1e-5f && std::abs(clip.y / clip.w) < 1e-5f);
    DirectionalLight light;
    light.elevationDeg = 90;
    QVERIFY(near(light.direction(), {0, 1, 0}));
}

void MeshTest::namesRoundTrip() {
    for (std::string_view name : meshKindNames())
        QCOMPARE(meshKindName(*parseMeshKind(name)), name);
    QVERIFY(!parseMeshKind("torus").has_value());
}

QTEST_APPLESS_MAIN(MeshTest)
#include "MeshTest.moc"

// A mesh is seen whole when it is shown: the camera keeps its angles and frames the mesh's bounding
// sphere in the view, whatever the view's shape (one, two or four viewports, a wide or a tall
// window); the plane fills the view as before (preview/ViewSettings.h framed()).

#include "StudioTestSupport.h"
#include "TestMeshes.h"
#include "panels/ViewPanel.h"

#include <QComboBox>
#include <glm/mat4x4.hpp>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

namespace {

// The largest |x| and |y| of the mesh's vertices on screen (normalised device coordinates: the
// view spans -1 to 1), and whether every vertex is in front of the camera.
struct Extent {
    double x = 0.0, y = 0.0;
    bool inFront = true;
};

Extent screenExtent(const SharedView& view, float aspect) {
    const MeshData mesh = view.meshData ? *view.meshData : makeMesh(view.mesh);
    const glm::mat4 m = view.camera.projection(aspect) * view.camera.view();
    Extent e;
    for (const MeshVertex& v : mesh.vertices) {
        const glm::vec4 clip = m * glm::vec4(v.position, 1.0f);
        e.inFront = e.inFront && clip.w > 0.0f;
        e.x = std::max(e.x, std::abs(double(clip.x / clip.w)));
        e.y = std::max(e.y, std::abs(double(clip.y / clip.w)));
    }
    return e;
}

} // namespace

class ViewFramingTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { isolateSettings(m_dir); }

    void newMeshesAreSeenWhole_data() {
        QTest::addColumn<int>("layout");
        QTest::addColumn<QSize>("window");
        QTest::addRow("1 view, wide") << 1 << QSize(1400, 700);
        QTest::addRow("1 view, tall") << 1 << QSize(700, 900);
        QTest::addRow("2 views") << 2 << QSize(1100, 560);
        QTest::addRow("4 views") << 4 << QSize(1400, 900);
    }
    void newMeshesAreSeenWhole() {
        QFETCH(int, layout);
        QFETCH(QSize, window);
        const QString torus = m_dir.filePath("torus.glb");
        QVERIFY(px::test::writeGltf(torus.toStdString(), px::test::torus(24, 12, false)));
        auto w = makeWindow(layout, 16);
        QVERIFY(w);
        w->resize(window);
        QTRY_COMPARE(w->size(), window);
        QCoreApplication::processEvents(); // the layouts follow
        ViewportGrid* grid = w->viewports();
        QComboBox* meshes = w->viewPanel()->mesh();
        auto check = [&](const QString& what) {
            const float aspect = grid->aspect(grid->activeViewport());
            const Extent e = screenExtent(grid->activeView(), aspect);
            const QString where =
                QString("%1 at aspect %2: |x| %3, |y| %4").arg(what).arg(aspect).arg(e.x).arg(e.y);
            QVERIFY2(e.inFront && e.x <= 1.0 && e.y <= 1.0, qPrintable(where)); // nothing cut
            QVERIFY2(std::max(e.x, e.y) >= 0.85, qPrintable(where));            // not lost in it
        };
        // Orbited first: the angles stay, the distance frames the mesh.
        SharedView orbited = grid->activeView();
        orbited.camera.azimuthDeg = 75.0f;
        orbited.camera.elevationDeg = 10.0f;
        grid->editView(orbited);
        for (const char* builtIn : {"sphere", "cube", "cylinder"}) {
            meshes->setCurrentIndex(meshes->findText(builtIn));
            QCOMPARE(grid->activeView().camera.azimuthDeg, 75.0f);
            check(builtIn);
        }
        QVERIFY(w->loadMesh(torus));
        check("torus.glb");
        // The camera is reset framing it too (View > Reset Camera, a double-click).
        grid->resetCameras();
        QCOMPARE(grid->activeView().camera.azimuthDeg, defaultCamera().azimuthDeg);
        check("torus.glb, camera reset");
        // The plane fills the view as it always did.
        meshes->setCurrentIndex(meshes->findText("plane"));
        QCOMPARE(grid->activeView().camera.distance, defaultCamera().distance);
    }

    // A zoomed view keeps its zoom when only the uv set of the mesh it shows changes.
    void theSameMeshKeepsItsCamera() {
        px::test::TestMesh torus = px::test::torus(16, 8, false);
        for (const glm::vec2& uv : torus.uvs)
            torus.uvs2.push_back(2.0f * uv);
        const QString file = m_dir.filePath("sets.glb");
        QVERIFY(px::test::writeGltf(file.toStdString(), torus));
        auto w = makeWindow(1, 16);
        QVERIFY(w);
        QVERIFY(w->loadMesh(file));
        SharedView zoomed = w->viewports()->activeView();
        zoomed.camera.distance = 5.5f;
        w->viewports()->editView(zoomed);
        QVERIFY(w->loadMesh(file, 1));
        QCOMPARE(w->viewports()->activeView().meshUvSet, 1);
        QCOMPARE(w->viewports()->activeView().camera.distance, 5.5f);
    }
};

QTEST_MAIN(ViewFramingTest)
#include "ViewFramingTest.moc"

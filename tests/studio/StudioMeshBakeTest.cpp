// Bake ▸ From Mesh… under Xvfb with llvmpipe: the menu's dialog reads the chosen mesh and shows
// its bounds and the tile; the bake makes a new material (height, normal and occlusion maps in
// memory, the height scale of the relief, the wrap) that the preview draws at once, and one Undo
// brings the previous material back; a cancelled bake and a tile without geometry change nothing.

#include "BakeTiles.h"
#include "StudioTestSupport.h"
#include "jobs/BackgroundLoad.h"
#include "model/MaterialDocument.h"
#include "panels/MeshBakeDialog.h"
#include "widgets/FileDialogs.h"

#include <QAction>
#include <QFileDialog>
#include <QLabel>
#include <QProgressDialog>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

class StudioMeshBakeTest : public GlWindowTest {
    Q_OBJECT

    // A periodic ground with a dome across the right edge on the 2 x 1 tile.
    QString writeTile() {
        px::test::TestMesh m = px::test::periodicGround({0, 0, 2, 1}, 48, 0.15, 0.4);
        px::test::append(m, px::test::dome({1.9, 0.5, 0.0}, 0.3, 48, 16));
        const QString file = m_dir.filePath("tile.ply");
        return px::test::writePlyBinary(file.toStdString(), m) ? file : QString();
    }

private slots:
    void initTestCase() { QVERIFY(glReady()); }

    void bakeMakesAnUndoableMaterial() {
        auto w = makeWindow();
        QVERIFY(w);
        const QString mesh = writeTile();
        QVERIFY(!mesh.isEmpty());
        const std::string before = w->document()->material().name;
        MeshBakeOptions o;
        o.tile = {0, 0, 2, 1};
        o.width = 64;
        o.height = 32;
        o.maps = {true, true, true};
        o.rays = 8;
        QVERIFY2(w->bakeFromMesh(mesh, o), qPrintable(w->lastProblem()));
        const DocumentState& s = w->document()->state();
        QCOMPARE(s.material.name, std::string("tile"));
        QVERIFY(s.hasMap(MapKind::Height) && s.hasMap(MapKind::Normal) && s.hasMap(MapKind::Ao));
        QVERIFY(s.isUnsaved(MapKind::Height) && s.isUnsaved(MapKind::Ao));
        QCOMPARE(s.assets->height.width, 64);
        QCOMPARE(s.assets->height.height, 32);
        QVERIFY(s.material.normalSource == NormalSource::Map);
        QVERIFY(s.material.wrap == WrapMode::Repeat);
        // The relief's true scale: (z1 - z0) / tile width, z from the ground's -0.15 to the
        // dome's 0.3.
        QVERIFY2(std::abs(s.material.heightScale - 0.45f / 2) < 0.01f,
                 qPrintable(QString::number(s.material.heightScale)));
        QVERIFY(w->statusBar()->currentMessage().contains("height scale"));
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        QVERIFY2(preview->renderError().isEmpty(), qPrintable(preview->renderError()));
        w->document()->undoStack()->undo();
        QCOMPARE(w->document()->material().name, before);
        QVERIFY(!w->document()->state().hasMap(MapKind::Ao));
    }

    // The menu item opens the dialog; choosing the file reads it, fills the bounds and the tile.
    void dialogShowsTheBoundsAndTile() {
        auto w = makeWindow();
        QVERIFY(w);
        const QString mesh = writeTile();
        QAction* item = nullptr;
        for (QAction* a : w->findChildren<QAction*>()) {
            if (a->text() == QStringLiteral("From &Mesh…"))
                item = a;
        }
        QVERIFY(item);
        const DialogRunner previous =
            setDialogRunner([mesh](QFileDialog&) { return QString(mesh); });
        item->trigger();
        auto* dialog = w->findChild<MeshBakeDialog*>(QStringLiteral("mesh-bake-dialog"));
        QVERIFY(dialog);
        QPushButton* choose = nullptr;
        for (QPushButton* b : dialog->findChildren<QPushButton*>()) {
            if (b->text() == QStringLiteral("Choose…"))
                choose = b;
        }
        QVERIFY(choose);
        choose->click();
        setDialogRunner(previous);
        QVERIFY(dialog->mesh());
        QVERIFY2(dialog->boundsText().startsWith("6096 triangles; X 0 to 2.2, Y 0 to 1"),
                 qPrintable(dialog->boundsText()));
        const MeshBakeOptions o = dialog->options();
        QVERIFY(std::abs(o.tile.x1 - dialog->mesh()->hi.x) < 1e-4); // as the fields round it
        QCOMPARE(o.width, 1024);
        QVERIFY(o.maps.height && o.maps.normal && o.maps.occlusion);
        dialog->reject();
    }

    // A tile far from the mesh: a message naming the file, and the material is the one before.
    void emptyTileChangesNothing() {
        auto w = makeWindow();
        QVERIFY(w);
        const QString mesh = writeTile();
        const std::string before = w->document()->material().name;
        MeshBakeOptions o;
        o.tile = {10, 10, 11, 11};
        QVERIFY(!w->bakeFromMesh(mesh, o));
        QVERIFY2(w->lastProblem().contains("tile.ply: the tile 10,10,11,11 holds no geometry"),
                 qPrintable(w->lastProblem()));
        QCOMPARE(w->document()->material().name, before);
    }

    // Cancel on the busy dialog: the material stays as it was.
    void cancelledBakeChangesNothing() {
        auto w = makeWindow();
        QVERIFY(w);
        const QString mesh = writeTile();
        const std::string before = w->document()->material().name;
        setBusyDialogDelay(0);
        // Cancel the bake's busy dialog once it shows (the mesh's read has one before it).
        QTimer poll;
        connect(&poll, &QTimer::timeout, &poll, [&w] {
            for (QProgressDialog* busy : w->findChildren<QProgressDialog*>()) {
                if (busy->isVisible() && busy->labelText().contains("Baking"))
                    QTest::mouseClick(busy->findChild<QPushButton*>(), Qt::LeftButton);
            }
        });
        poll.start(20);
        MeshBakeOptions o;
        o.tile = {0, 0, 2, 1};
        o.width = o.height = 2048;
        o.samples = 4;
        o.maps = {true, true, false};
        const bool baked = w->bakeFromMesh(mesh, o);
        setBusyDialogDelay(300);
        QVERIFY(!baked);
        QCOMPARE(w->document()->material().name, before);
        QVERIFY(w->statusBar()->currentMessage().contains("cancelled"));
    }
};

QTEST_MAIN(StudioMeshBakeTest)
#include "StudioMeshBakeTest.moc"

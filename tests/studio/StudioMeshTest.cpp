// The editor's own mesh, under Xvfb with llvmpipe: Load Mesh draws the file in the viewport (the
// error figures still measured), drops load meshes, the recent meshes list them and pick them
// again, the material's mesh comes back when the material is opened again, and a bad mesh is a
// message naming the file that keeps the mesh drawn before.

#include "StudioTestSupport.h"
#include "TestMeshes.h"
#include "jobs/BackgroundLoad.h"
#include "panels/ViewPanel.h"
#include "parallax/image/ImageFile.h"
#include "parallax/mesh/MeshLoader.h"
#include "preview/ViewInteraction.h"
#include "widgets/SliderField.h"
#include "widgets/TechniqueCombo.h"
#include "window/RecentFiles.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileInfo>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>
#include <QThreadPool>
#include <QTimer>
#include <QToolButton>
#include <atomic>
#include <future>
#include <limits>
#include <random>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

class StudioMeshTest : public GlWindowTest {
    Q_OBJECT

    QString write(const char* name, const px::test::TestMesh& mesh) {
        const QString file = m_dir.filePath(name);
        const bool ok = file.endsWith(".obj") ? px::test::writeObj(file.toStdString(), mesh)
                                              : px::test::writeGltf(file.toStdString(), mesh);
        return ok ? file : QString();
    }

private slots:
    void initTestCase() { QVERIFY(glReady()); }

    void loadedMeshIsDrawnAndMeasured() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        const QImage plane = preview->grabFramebuffer();
        const QString torus = write("torus.glb", px::test::torus(32, 16, false));
        QVERIFY(w->loadMesh(torus));
        // Said as it loads, for 10 s: checked now, not after the frames a loaded machine may
        // take longer than that to draw.
        QVERIFY2(w->statusBar()->currentMessage().contains("1024 triangles"),
                 qPrintable(w->statusBar()->currentMessage()));
        QVERIFY(preview->scene().view.meshData);
        QCOMPARE(preview->scene().view.meshFile, QFileInfo(torus).absoluteFilePath());
        QVERIFY(waitForFigures(preview));
        QVERIFY2(preview->renderError().isEmpty(), qPrintable(preview->renderError()));
        // The error readout goes on on the mesh: the same mesh in the exact pass.
        QVERIFY(preview->stats().pixels > 0);
        QVERIFY(preview->stats().p99Error >= 0.0);
        const QImage drawn = preview->grabFramebuffer();
        QVERIFY(changedPixels(plane, drawn) > drawn.width() * drawn.height() / 20);
        QCOMPARE(w->viewPanel()->mesh()->currentText(), QString("torus.glb"));
        QCOMPARE(w->recentMeshes()->files().value(0), QFileInfo(torus).absoluteFilePath());

        // Back to a built-in mesh from the list, then the torus again from the recent meshes.
        QComboBox* combo = w->viewPanel()->mesh();
        combo->setCurrentIndex(combo->findText("sphere"));
        QVERIFY(!preview->scene().view.meshData);
        QVERIFY(preview->scene().view.mesh == MeshKind::Sphere);
        combo->setCurrentIndex(combo->findText("torus.glb"));
        QVERIFY(preview->scene().view.meshData);
        QVERIFY(waitForFigures(preview));
    }

    void errorReadoutOnATorus_data() {
        QTest::addColumn<int>("technique");
        QTest::newRow("pom") << static_cast<int>(Technique::Pom);
        QTest::newRow("relief") << static_cast<int>(Technique::Relief);
    }

    // The error readout on a mesh counts the pixels where the view meets the surface at most 89
    // degrees from its interpolated normal, as on the plane (docs/meshes.md). A torus's rims are
    // steeper; past 90 degrees there is no ray into the relief at all (the shader holds the view
    // at a grazing angle, P about 10^4 s), and counting them put pom's and relief's max error at
    // 10^5 texels. They are counted apart now, and the torus's max error (every pixel: the heat
    // map on) is of the order of the plane's seen at the same angles: from the orbit's lowest
    // point, 1 degree above it, where its far pixels reach 89 degrees.
    void errorReadoutOnATorus() {
        QFETCH(int, technique);
        auto w = makeWindow();
        QVERIFY(w);
        Viewport* viewport = w->viewports()->viewport(0);
        PreviewWidget* preview = viewport->preview();
        emit viewport->techniqueCombo()->techniqueChosen(static_cast<Technique>(technique));
        QCOMPARE(preview->scene().material.technique, static_cast<Technique>(technique));
        QTest::mouseClick(viewport->heatMapButton(), Qt::LeftButton);
        QVERIFY(preview->scene().overlays.heatMap);
        SharedView view = w->viewports()->activeView();
        view.camera = withPolarAngle(view.camera, 89.0);
        w->viewports()->editView(view);
        QVERIFY(waitForFigures(preview));
        const PreviewStats plane = preview->stats();
        view.camera = defaultCamera();
        w->viewports()->editView(view);
        QVERIFY(w->loadMesh(write("readout.glb", px::test::torus(32, 16, false))));
        QVERIFY(waitForFigures(preview));
        const PreviewStats torus = preview->stats();
        qInfo("%s, bricks 64: plane at 89 degrees: max %.3g texels over %d px (%d steeper); "
              "torus: max %.3g, p99 %.3g, mean %.3g over %d px (%d steeper)",
              info(static_cast<Technique>(technique)).name.data(), plane.maxError, plane.pixels,
              plane.steepPixels, torus.maxError, torus.p99Error, torus.meanError, torus.pixels,
              torus.steepPixels);
        QVERIFY(plane.pixels > 0 && plane.maxError > 0.0);
        QVERIFY(torus.pixels > 0 && torus.steepPixels > 0);
        QVERIFY2(torus.maxError <= 2.0 * plane.maxError,
                 qPrintable(QString("torus %1, plane %2").arg(torus.maxError).arg(plane.maxError)));
        QVERIFY(viewport->statsText().contains("px steeper than 89°"));
    }

    // Rays whose exact hit lies off the surface the view shows (under a silhouette the relief's
    // locally flat model runs on for tiles) are left out of the figures and said: on meshes of
    // every kind seen from seeded angles, what is counted stays within the plane's worst at 89
    // degrees, and the readout names what it left out.
    void errorReadoutLeavesOutHitsOffTheVisibleSurface_data() {
        QTest::addColumn<QString>("mesh");
        QTest::addColumn<unsigned>("seed");
        const std::pair<const char*, unsigned> rows[] = {{"torus.glb", 5u},
                                                         {"sphere.glb", 1234u},
                                                         {"mirrored.glb", 1234u},
                                                         {"cube", 5u},
                                                         {"cylinder", 1234u}};
        for (const auto& [mesh, seed] : rows)
            QTest::addRow("%s, seed %u", mesh, seed) << QString(mesh) << seed;
    }
    void errorReadoutLeavesOutHitsOffTheVisibleSurface() {
        QFETCH(QString, mesh);
        QFETCH(unsigned, seed);
        auto w = makeWindow();
        QVERIFY(w);
        Viewport* viewport = w->viewports()->viewport(0);
        PreviewWidget* preview = viewport->preview();
        QTest::mouseClick(viewport->heatMapButton(), Qt::LeftButton);
        SharedView view = w->viewports()->activeView();
        view.camera = withPolarAngle(view.camera, 89.0);
        w->viewports()->editView(view);
        QVERIFY(waitForFigures(preview));
        const double planeMax = preview->stats().maxError;
        if (mesh == "torus.glb")
            QVERIFY(w->loadMesh(write("torus.glb", px::test::torus(32, 16, false))));
        else if (mesh == "sphere.glb")
            QVERIFY(w->loadMesh(write("sphere.glb", px::test::seamedSphere(32, 16))));
        else if (mesh == "mirrored.glb")
            QVERIFY(w->loadMesh(write("mirrored.glb", px::test::mirroredSphere(32, 16))));
        else
            w->viewPanel()->mesh()->setCurrentIndex(w->viewPanel()->mesh()->findText(mesh));
        std::mt19937 rng(seed);
        view = w->viewports()->activeView();
        view.camera.azimuthDeg = std::uniform_real_distribution<float>(0.0f, 360.0f)(rng);
        view.camera.elevationDeg = std::uniform_real_distribution<float>(-60.0f, 75.0f)(rng);
        w->viewports()->editView(view);
        QVERIFY(waitForFigures(preview));
        const PreviewStats& st = preview->stats();
        qInfo("%s, seed %u: max %.4g, p99 %.4g, mean %.4g texels over %d px; left out %d px "
              "steeper than 89, %d px off the visible surface; the plane at 89: max %.4g",
              qPrintable(mesh), seed, st.maxError, st.p99Error, st.meanError, st.pixels,
              st.steepPixels, st.offRegionPixels, planeMax);
        QVERIFY(st.pixels > 0);
        QVERIFY2(st.maxError <= 2.0 * planeMax, qPrintable(viewport->statsText()));
        if (st.offRegionPixels > 0)
            QVERIFY(viewport->statsText().contains(
                QString("%1 px whose exact hit is off the visible surface")
                    .arg(st.offRegionPixels)));
    }

    void droppedMeshLoadsAndBadMeshKeepsTheLastOne() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        const QString sphere = write("sphere.obj", px::test::seamedSphere(32, 16));
        QVERIFY(dropFiles(w.get(), {sphere}));
        QCOMPARE(preview->scene().view.meshFile, QFileInfo(sphere).absoluteFilePath());
        QVERIFY(waitForFigures(preview));
        QVERIFY(w->lastProblem().isEmpty());

        px::test::TestMesh nan = px::test::torus(16, 8, false);
        nan.positions[2].z = std::numeric_limits<float>::quiet_NaN();
        const QString bad = write("nan.obj", nan);
        QVERIFY(dropFiles(w.get(), {bad}));
        QVERIFY2(w->lastProblem().startsWith(bad + ": vertex"), qPrintable(w->lastProblem()));
        QVERIFY(w->lastProblem().contains("non-finite position"));
        QCOMPARE(preview->scene().view.meshFile, QFileInfo(sphere).absoluteFilePath());
        QCOMPARE(w->viewPanel()->mesh()->currentText(), QString("sphere.obj"));
        QVERIFY(!w->loadMesh(m_dir.filePath("missing.gltf")));
        QCOMPARE(w->lastProblem(), m_dir.filePath("missing.gltf") + ": no such file");
    }

    // A file with two uv sets: the uv spin box offers both and reads the mesh again with the one
    // chosen (the second repeats the texture twice as often).
    void uvSetIsChosen() {
        auto w = makeWindow();
        QVERIFY(w);
        px::test::TestMesh torus = px::test::torus(16, 8, false);
        for (const glm::vec2& uv : torus.uvs)
            torus.uvs2.push_back(2.0f * uv);
        const QString file = write("two-sets.glb", torus);
        QSpinBox* uvSet = w->viewPanel()->uvSet();
        QVERIFY(!uvSet->isEnabled()); // the built-in plane has one
        QVERIFY(w->loadMesh(file));
        QVERIFY(uvSet->isEnabled());
        QCOMPARE(uvSet->maximum(), 1);
        const std::shared_ptr<const MeshData> first = w->viewports()->activeView().meshData;
        uvSet->setValue(1);
        const SharedView& view = w->viewports()->activeView();
        QCOMPARE(view.meshUvSet, 1);
        QVERIFY(view.meshData != first);
        QCOMPARE(view.meshData->vertices.size(), first->vertices.size());
        for (std::size_t i = 0; i < first->vertices.size(); ++i)
            QVERIFY(glm::length(view.meshData->vertices[i].uv - 2.0f * first->vertices[i].uv) <
                    1e-5f);
        QVERIFY(w->statusBar()->currentMessage().contains("uv set 1 of 2"));
    }

    // The uv set goes with a remembered mesh: the recent meshes read a file again with the set it
    // was last shown with, a material opened again gets its mesh with its set, and a set the file
    // no longer has falls back to the first without a message.
    void uvSetIsRemembered() {
        const QString material = m_dir.filePath("uv-set.json");
        px::test::TestMesh torus = px::test::torus(16, 8, false);
        for (const glm::vec2& uv : torus.uvs)
            torus.uvs2.push_back(2.0f * uv);
        const QString file = write("sets.glb", torus);
        {
            auto w = makeWindow();
            QVERIFY(w);
            QVERIFY(w->saveTo(material));
            QVERIFY(w->loadMesh(file));
            QCOMPARE(w->viewports()->activeView().meshUvSet, 0);
            w->viewPanel()->uvSet()->setValue(1);
            QCOMPARE(w->viewports()->activeView().meshUvSet, 1);
            QCOMPARE(MainWindow::rememberedMeshUvSet(material), 1);
            QComboBox* combo = w->viewPanel()->mesh();
            combo->setCurrentIndex(combo->findText("cube"));
            QVERIFY(!w->viewports()->activeView().meshData);
            combo->setCurrentIndex(combo->findText("sets.glb"));
            QCOMPARE(w->viewports()->activeView().meshUvSet, 1);
            QCOMPARE(w->viewPanel()->uvSet()->value(), 1);
            QVERIFY(w->statusBar()->currentMessage().contains("uv set 1 of 2"));
        }
        {
            auto w = makeWindow(); // another session: the settings are what it has
            QVERIFY(w);
            QVERIFY(w->openFile(material));
            QCOMPARE(w->viewports()->activeView().meshFile, QFileInfo(file).absoluteFilePath());
            QCOMPARE(w->viewports()->activeView().meshUvSet, 1);
            QComboBox* combo = w->viewPanel()->mesh();
            combo->setCurrentIndex(combo->findText("sphere"));
            // Choosing set 0 is remembered too.
            combo->setCurrentIndex(combo->findText("sets.glb"));
            QCOMPARE(w->viewports()->activeView().meshUvSet, 1);
            w->viewPanel()->uvSet()->setValue(0);
            QCOMPARE(MainWindow::rememberedMeshUvSet(material), 0);
            w->viewPanel()->uvSet()->setValue(1);
        }
        QVERIFY(!write("sets.glb", px::test::torus(16, 8, false)).isEmpty()); // one set now
        auto w = makeWindow();
        QVERIFY(w);
        QVERIFY(w->openFile(material));
        QCOMPARE(w->viewports()->activeView().meshFile, QFileInfo(file).absoluteFilePath());
        QCOMPARE(w->viewports()->activeView().meshUvSet, 0);
        QVERIFY2(w->lastProblem().isEmpty(), qPrintable(w->lastProblem()));
    }

    // A mesh load reports its progress: with the dialog's delay at 0 (a large mesh waits 300 ms
    // for it) the dialog shows at once; the test holds the load on its loading thread at its
    // first report past 0 until the dialog's bar shows it, then lets it go and the mesh arrives.
    // Cancelled at the same point, the mesh drawn before stays.
    void meshLoadReportsProgress() {
        setBusyDialogDelay(0);
        auto w = makeWindow();
        QVERIFY(w);
        const QString file = write("progress.glb", px::test::torus(64, 32, false));
        for (const bool cancel : {false, true}) {
            auto release = std::make_shared<std::promise<void>>();
            std::shared_future<void> released = release->get_future().share();
            auto held = std::make_shared<std::atomic<bool>>(false);
            w->setMeshProgressObserver([held, released](float f) {
                if (f > 0.0f && !held->exchange(true))
                    released.wait();
            });
            int shownValue = -1;
            QString label;
            QTimer poll;
            connect(&poll, &QTimer::timeout, this, [&] {
                auto* dialog = w->findChild<QProgressDialog*>();
                if (shownValue >= 0 || !held->load() || !dialog || !dialog->isVisible() ||
                    dialog->value() <= 0)
                    return;
                shownValue = dialog->value();
                label = dialog->labelText();
                if (cancel) // the load stays held until loadMesh has returned
                    QTest::mouseClick(dialog->findChild<QPushButton*>(), Qt::LeftButton);
                else
                    release->set_value();
            });
            poll.start(5);
            const std::shared_ptr<const MeshData> before = w->viewports()->activeView().meshData;
            const bool loaded = w->loadMesh(file);
            poll.stop();
            if (cancel)
                release->set_value(); // the worker ends on its own; its mesh is dropped
            qInfo("%s: the dialog's bar at %d %% while the load was held",
                  cancel ? "cancel" : "load", shownValue);
            QVERIFY2(shownValue > 0 && shownValue <= 100, qPrintable(QString::number(shownValue)));
            QVERIFY2(label.startsWith("Loading progress.glb…"), qPrintable(label));
            QCOMPARE(loaded, !cancel);
            if (cancel) {
                QVERIFY(w->viewports()->activeView().meshData == before);
                QVERIFY(w->statusBar()->currentMessage().contains("cancelled"));
            } else {
                QVERIFY(w->viewports()->activeView().meshData);
                QCOMPARE(w->viewports()->activeView().meshData->indices.size(),
                         std::size_t(3 * 64 * 32 * 2));
            }
        }
        w->setMeshProgressObserver({});
        QThreadPool::globalInstance()->waitForDone(); // the cancelled load ends on its own
        setBusyDialogDelay(300);
    }

    // The mesh belongs to the editor's settings for the material file, not to the file.
    void materialRemembersItsMesh() {
        const QString material = m_dir.filePath("bricks.json");
        const QString torus = write("remembered.gltf", px::test::torus(24, 12, true));
        {
            auto w = makeWindow();
            QVERIFY(w);
            QVERIFY(w->saveTo(material));
            QVERIFY(w->loadMesh(torus));
            QCOMPARE(MainWindow::rememberedMesh(material), QFileInfo(torus).absoluteFilePath());
        }
        QFile file(material);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(!file.readAll().contains("remembered.gltf"));
        auto w = makeWindow();
        QVERIFY(w);
        QVERIFY(!w->viewports()->activeView().meshData);
        QVERIFY(w->openFile(material));
        QCOMPARE(w->viewports()->activeView().meshFile, QFileInfo(torus).absoluteFilePath());
        QVERIFY(w->viewports()->activeView().meshData);
        // A built-in mesh chosen for it is remembered too: no mesh file.
        QComboBox* combo = w->viewPanel()->mesh();
        combo->setCurrentIndex(combo->findText("cube"));
        QVERIFY(MainWindow::rememberedMesh(material).isEmpty());
    }

    // The sky lights the view (and shows behind it), exposure brightens it, hiding the sky
    // brings the backdrop back, and a file that is no environment is a message naming it.
    void environmentLightsTheView() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        const QImage plain = preview->grabFramebuffer();
        QComboBox* environment = w->viewPanel()->environment();
        environment->setCurrentIndex(environment->findData(QStringLiteral("sky")));
        QVERIFY(preview->scene().view.environment);
        QCOMPARE(preview->scene().view.environmentName, QString("sky"));
        QVERIFY(waitForFigures(preview));
        QVERIFY2(preview->renderError().isEmpty(), qPrintable(preview->renderError()));
        const QImage sky = preview->grabFramebuffer();
        QVERIFY(changedPixels(plain, sky) > sky.width() * sky.height() / 4);
        QVERIFY(preview->stats().pixels > 0); // the error readout goes on

        w->viewPanel()->exposure()->setValue(1.5);
        emit w->viewPanel()->exposure()->valueEdited(1.5);
        QCOMPARE(preview->scene().view.exposure, 1.5f);
        QVERIFY(waitForFigures(preview));
        const QImage brighter = preview->grabFramebuffer();
        double before = 0.0, after = 0.0;
        // The panel's re-layout may resize the view by a few pixels: compare what both cover.
        const int width = std::min(sky.width(), brighter.width());
        const int height = std::min(sky.height(), brighter.height());
        for (int y = 0; y < height; y += 4)
            for (int x = 0; x < width; x += 4) {
                before += qGray(sky.pixel(x, y));
                after += qGray(brighter.pixel(x, y));
            }
        QVERIFY2(after > before * 1.1, qPrintable(QString("%1 -> %2").arg(before).arg(after)));

        w->viewPanel()->showEnvironment()->setChecked(false);
        QVERIFY(!preview->scene().view.showEnvironment);
        QVERIFY(waitForFigures(preview));
        const QImage hidden = preview->grabFramebuffer();
        QCOMPARE(hidden.pixel(2, 2), plain.pixel(2, 2)); // the corner: the backdrop again

        const QString square = m_dir.filePath("square.exr");
        ImageWriteOptions exr;
        exr.format = PixelFormat::Half;
        QVERIFY(writeImage(square.toStdString(), Image(16, 16, 3), exr).ok());
        QVERIFY(!w->setEnvironment(square));
        QVERIFY2(w->lastProblem().startsWith(square + ": is 16 x 16"),
                 qPrintable(w->lastProblem()));
        QCOMPARE(preview->scene().view.environmentName, QString("sky"));
        environment->setCurrentIndex(0); // none
        QVERIFY(!preview->scene().view.environment);
    }
};

QTEST_MAIN(StudioMeshTest)
#include "StudioMeshTest.moc"

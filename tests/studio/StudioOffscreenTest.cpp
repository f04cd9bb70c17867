// The editor's parts that need no OpenGL, on Qt's offscreen platform: the placeholder in place of
// the live preview, the "no OpenGL 4.3" message, the Compare panel (bench in the background,
// progress, cancel, a click on the plot applies a setting), the command line, export, saving.

#include "StudioTestSupport.h"
#include "jobs/BackgroundLoad.h"
#include "jobs/Baking.h"
#include "model/SampleMaterial.h"
#include "panels/ComparePanel.h"
#include "panels/ExportDialog.h"
#include "panels/MapRow.h"
#include "panels/MapsPanel.h"
#include "panels/MaterialPanel.h"
#include "panels/TechniquePanel.h"
#include "panels/WorkPrecisionView.h"
#include "parallax/eval/AutoTechnique.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/sample/ProceduralMaps.h"
#include "preview/GlUnavailableDialog.h"
#include "widgets/RangeSlider.h"
#include "widgets/SliderField.h"
#include "widgets/TechniqueCombo.h"
#include "window/RecentFiles.h"
#include "window/StudioOptions.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>
#include <algorithm>
#include <future>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

class StudioOffscreenTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { isolateSettings(m_dir); }

    void placeholderWhereThereIsNoGl() {
        const GlProbe& gl = probeOpenGl();
        QVERIFY(gl.offscreenPlatform);
        QVERIFY(!gl.usable);
        MainWindow w(gl.reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Stones, 32);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.viewports()->viewport(0)->preview() == nullptr);
        QVERIFY(w.viewports()->viewport(0)->statsText().contains("pom"));
    }

    // A load runs on a worker while the GUI thread keeps handling events; past a quiet moment a
    // window-modal dialog names the file, and Cancel returns at once with nothing loaded. The
    // load is held by a promise the test keeps, so nothing here depends on how fast a machine is.
    void loadsInTheBackgroundAndCancels() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        for (bool cancel : {false, true}) {
            std::promise<void> release;
            std::shared_future<void> released = release.get_future().share();
            int ticks = 0;
            QString shown;
            QTimer poll;
            connect(&poll, &QTimer::timeout, this, [&] {
                ++ticks;
                auto* dialog = w.findChild<QProgressDialog*>();
                if (!dialog || !dialog->isVisible())
                    return;
                if (!shown.isEmpty())
                    return; // acted on already
                shown = dialog->labelText();
                if (cancel)
                    QTest::mouseClick(dialog->findChild<QPushButton*>(), Qt::LeftButton);
                else
                    release.set_value();
            });
            poll.start(10);
            const Result<int> loaded = loadInBackground<int>(&w, "big.png", [released] {
                released.wait();
                return Result<int>(7);
            });
            poll.stop();
            QVERIFY2(shown.startsWith("Loading big.png…"), qPrintable(shown));
            QVERIFY(ticks > 1); // the GUI thread ran while the load was held
            if (cancel) {
                release.set_value(); // the worker ends on its own; its result is dropped
                QVERIFY(!loaded.ok() && loaded.error().cancelled());
            } else {
                QVERIFY(loaded.ok() && *loaded == 7);
            }
            QTRY_VERIFY(!w.findChild<QProgressDialog*>());
        }
    }

    // Loading a map from the window goes through the worker: events run during loadMap (on the
    // GUI thread a 2048² decode ran with none).
    void loadMapKeepsTheWindowAlive() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 32);
        const std::string file = m_dir.filePath("big_height.png").toStdString();
        QVERIFY(writeImage(file, makeProceduralMap(ProceduralMap::Noise, 2048, 2048).toImage(),
                           {PixelFormat::UInt16, false}));
        int ticks = 0;
        QTimer poll;
        connect(&poll, &QTimer::timeout, this, [&] { ++ticks; });
        poll.start(0);
        QVERIFY(w.loadMap(MapKind::Height, QString::fromStdString(file)));
        poll.stop();
        QVERIFY(ticks > 0);
        QCOMPARE(w.document()->state().assets->height.width, 2048);
    }

    // Auto in the editor: Pick measures on the material's height map, makes the choice the
    // material's (still "auto", with the fields' budget and angle), says what it chose; the same
    // inputs resolved directly give the same setting. A technique chosen by hand ends auto.
    void autoPicksTheCheapestAndAHandChoiceEndsIt() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 48);
        TechniquePanel* panel = w.techniquePanel();
        panel->setViewport(0);
        QVERIFY(panel->autoStatus().contains("by hand"));
        panel->autoBudget()->setValue(0.25);
        panel->autoMaxPolar()->setValue(70.0);
        panel->autoPick()->click();
        const Material m = w.document()->material();
        QVERIFY2(m.autoQuality.has_value(), qPrintable(panel->autoStatus()));
        QCOMPARE(m.autoQuality->budget, 0.25f);
        QCOMPARE(m.autoQuality->maxPolar, 70.0f);

        Material asked = m;
        asked.technique = Technique::Pom;
        asked.params = info(Technique::Pom).defaults;
        const MaterialAssets& a = *w.document()->state().assets;
        const Result<ResolvedAuto> direct =
            resolveAutoTechnique(asked, a.height, a.cone, a.relaxedCone, "direct");
        QVERIFY(direct.ok());
        QCOMPARE(m.technique, direct->material.technique);
        QCOMPARE(m.params.minLayers, direct->material.params.minLayers);
        QCOMPARE(m.params.maxLayers, direct->material.params.maxLayers);
        QCOMPARE(m.params.binarySteps, direct->material.params.binarySteps);
        QCOMPARE(m.params.maxSteps, direct->material.params.maxSteps);
        const QString name = QString::fromUtf8(info(m.technique).name.data());
        QVERIFY2(panel->autoStatus().contains(name), qPrintable(panel->autoStatus()));

        // The chart shows every setting measured at the steepest view, the choice ringed.
        WorkPrecisionView* chart = panel->autoChart();
        QVERIFY(chart->hasPanel() && !chart->isHidden());
        QCOMPARE(chart->panel().polarDeg, 70.0);
        QVERIFY(chart->highlight().has_value());
        const WorkPrecisionPoint& ringed = chart->panel().at(*chart->highlight());
        QCOMPARE(ringed.setting.technique, m.technique);
        QCOMPARE(ringed.setting.label, direct->recommendation->chosen.setting.label);
        QCOMPARE(ringed.error, direct->recommendation->chosen.angles.front().p99);
        QVERIFY(ringed.error <= 0.25);
        QCOMPARE(ringed.onFront, direct->recommendation->chosen.onFront);
        QVERIFY2(panel->autoStatus().contains("Pareto front"), qPrintable(panel->autoStatus()));
        std::size_t points = 0;
        for (const WorkPrecisionSeries& series : chart->panel().series)
            points += series.points.size();
        // Settings given up mid-trace as dearer than the choice have no figures to plot.
        const auto measuredThere = std::count_if(
            direct->recommendation->measured.begin(), direct->recommendation->measured.end(),
            [](const MeasuredSetting& s) { return !s.angles.empty(); });
        QCOMPARE(points, static_cast<std::size_t>(measuredThere));

        // By hand: the combo's choice replaces auto.
        const Technique other =
            m.technique == Technique::Relief ? Technique::Pom : Technique::Relief;
        emit panel->techniqueCombo()->techniqueChosen(other);
        QCOMPARE(w.document()->material().technique, other);
        QVERIFY(!w.document()->material().autoQuality);
        QVERIFY(panel->autoStatus().contains("by hand"));
        QVERIFY(!chart->hasPanel() && chart->isHidden());
    }

    void noGlMessageNamesBothVersions() {
        GlProbe probe;
        probe.major = 3;
        probe.minor = 3;
        probe.renderer = "softpipe";
        const QString text = glUnavailableMessage(probe);
        QVERIFY2(text.contains("4.3") && text.contains("3.3") && text.contains("softpipe"),
                 qPrintable(text));
        QVERIFY(glUnavailableMessage(GlProbe{}).contains("no OpenGL"));
    }

    void compareRunsInTheBackgroundAndAClickAppliesAPoint() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 32);
        w.viewports()->setLayoutCount(2);
        w.viewports()->setActiveViewport(1);
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ComparePanel* compare = w.comparePanel();
        compare->parentWidget()->show();
        compare->raysField()->setValue(8);
        QSignalSpy finished(compare, &ComparePanel::finished);
        QTest::mouseClick(compare->runButton(), Qt::LeftButton);
        QVERIFY(compare->isRunning()); // returned at once: the bench runs on a worker
        QVERIFY(compare->cancelButton()->isEnabled());
        QVERIFY(finished.wait(120000));
        QVERIFY(compare->chart().has_value());
        // R × R rays, said so (a superscript two after %2 would be read as placeholder %22).
        QVERIFY2(compare->statusText().contains("8 × 8 rays per view angle"),
                 qPrintable(compare->statusText()));
        QCOMPARE(compare->raysField()->text(), QString("8 per side"));
        // The Cost box shows its whole text.
        QComboBox* axis = compare->axisCombo();
        QTRY_VERIFY(axis->width() >= axis->fontMetrics().horizontalAdvance(axis->currentText()));
        // GPU milliseconds measured on this machine's GL (llvmpipe on CI): a third cost panel,
        // which exists only when every pooled point was timed.
        QCOMPARE(compare->chart()->axes.back(), CostAxis::GpuTime);
        QCOMPARE(compare->axisCombo()->count(), 3);
        QVERIFY(compare->statusText().contains("GPU: ")); // the renderer and timing method
        // No GL on the offscreen platform, so no context to share: a headless one, said so.
        QVERIFY2(compare->statusText().contains("headless"), qPrintable(compare->statusText()));
        WorkPrecisionView* view = compare->chartView();
        QVERIFY(view->hasPanel());
        view->resize(700, 400);

        // Click relief's most expensive setting: viewport 2 takes it.
        const WorkPrecisionPanel& panel = view->panel();
        std::optional<PointRef> relief;
        for (std::size_t s = 0; s < panel.series.size(); ++s) {
            if (panel.series[s].technique == Technique::Relief)
                relief = PointRef{s, panel.series[s].points.size() - 1};
        }
        QVERIFY(relief);
        const WorkPrecisionPoint point = panel.at(*relief);
        QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier,
                          view->pointPosition(*relief).toPoint());
        const ViewQuality q = w.document()->state().view(1);
        QCOMPARE(q.technique, Technique::Relief);
        QCOMPARE(q.params.maxLayers, point.setting.params.maxLayers);
        QCOMPARE(q.params.minLayers, point.setting.params.minLayers);
        QCOMPARE(w.techniquePanel()->viewport(), 1);
        QCOMPARE(int(w.techniquePanel()->maxLayers()->value()), point.setting.params.maxLayers);
        // A view setting: no undo step, and the material (viewport 1) is untouched.
        QCOMPARE(w.document()->material().technique, Technique::Pom);
        QCOMPARE(w.document()->undoStack()->count(), 0);
        QVERIFY(!w.document()->isDirty());
    }

    void compareCancels() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 128);
        ComparePanel* compare = w.comparePanel();
        compare->raysField()->setValue(256);
        QSignalSpy finished(compare, &ComparePanel::finished);
        compare->run();
        QVERIFY(compare->isRunning());
        QTest::mouseClick(compare->cancelButton(), Qt::LeftButton);
        QVERIFY(finished.wait(120000));
        QVERIFY(!compare->chart().has_value());
        QVERIFY(compare->runButton()->isEnabled());
    }

    void commandLine() {
        Result<StudioOptions> o = parseStudioOptions(
            {"--screenshot", "a.png", "--layout", "4", "--techniques", "pom,relief,cone,exact"});
        QVERIFY(o);
        QCOMPARE(o->screenshot, QString("a.png"));
        QCOMPARE(o->layout, 4);
        QCOMPARE(o->techniques.size(), std::size_t(4));
        QCOMPARE(o->techniques[2], Technique::Cone);
        o = parseStudioOptions({"wall.json"});
        QVERIFY(o);
        QCOMPARE(o->file, QString("wall.json"));
        QCOMPARE(o->layout, 0);
        QVERIFY(!parseStudioOptions({"--layout", "3"}));
        QVERIFY(!parseStudioOptions({"--techniques", "pom,warp"}));
        QVERIFY(!parseStudioOptions({"--layout", "1", "--techniques", "pom,relief"}));
        QVERIFY(!parseStudioOptions({"--frobnicate"}));
        QVERIFY(!parseStudioOptions({"--screenshot"}));
        QVERIFY(!parseStudioOptions({"a.json", "b.json"}));
    }

    void saveThroughTheWindowAndExport() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Rivets, 32);
        w.document()->edit("scale", [](DocumentState& s) { s.material.heightScale = 0.03f; });
        QVERIFY(w.document()->isDirty());
        QVERIFY(w.windowTitle().contains("rivets"));
        const QString file = m_dir.filePath("rivets.json");
        QVERIFY(w.saveTo(file));
        QVERIFY(!w.document()->isDirty());
        QVERIFY(!w.isWindowModified());
        QVERIFY(w.windowTitle().contains("rivets.json"));
        QCOMPARE(w.recentFiles()->files().front(), QFileInfo(file).absoluteFilePath());
        QVERIFY(QFile::exists(m_dir.filePath("rivets_height.png")));

        ExportDialog dialog(w.document()->material(), w.document()->filePath(), &w);
        QSignalSpy done(&dialog, &ExportDialog::exportFinished);
        dialog.startExport();
        QVERIFY(done.wait(60000));
        QVERIFY2(done.front().front().toBool(), qPrintable(dialog.resultText()));
        QVERIFY(QFile::exists(m_dir.filePath("rivets-export/.parallax-export")));
        // Again without "replace": refused, the folder is left as it was.
        dialog.startExport();
        QVERIFY(done.wait(60000));
        QVERIFY(!done.back().front().toBool());
        // In the words of this dialog, not the command line's.
        QVERIFY2(!dialog.resultText().contains("--force"), qPrintable(dialog.resultText()));
        QVERIFY(dialog.resultText().contains(
            "already exists; tick \"Replace a previous export in this folder\" to replace it"));

        QVERIFY(w.openFile(file));
        QCOMPARE(w.document()->material().heightScale, 0.03f);
    }

    // The light the material was seen under is written into its file and comes back with it;
    // a file without one leaves the light as it is.
    void theLightIsSavedWithTheMaterial() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Stones, 16);
        SharedView view = w.viewports()->activeView();
        view.light.azimuthDeg = -63.0f;
        view.light.elevationDeg = 22.5f;
        w.viewports()->editView(view);
        const QString file = m_dir.filePath("lit.json");
        QVERIFY(w.saveTo(file));
        Result<Material> saved = loadMaterial(file.toStdString());
        QVERIFY(saved);
        QVERIFY(saved->light == (LightDirection{-63.0f, 22.5f}));
        QVERIFY(!w.document()->isDirty()); // what was saved is the clean state

        view = w.viewports()->activeView();
        view.light.azimuthDeg = 100.0f;
        view.light.elevationDeg = 70.0f;
        w.viewports()->editView(view);
        QVERIFY(w.openFile(file));
        QCOMPARE(w.viewports()->activeView().light.azimuthDeg, -63.0f);
        QCOMPARE(w.viewports()->activeView().light.elevationDeg, 22.5f);

        // Without a light in the file the view keeps its own.
        Material unlit = *saved;
        unlit.light.reset();
        const QString plain = m_dir.filePath("unlit.json");
        QVERIFY(saveMaterial(unlit, plain.toStdString()).ok());
        QVERIFY(!QString::fromStdString(materialToJson(unlit)).contains("\"light\""));
        QVERIFY(w.openFile(plain));
        QCOMPARE(w.viewports()->activeView().light.azimuthDeg, -63.0f);
    }

    // File > New Empty Material: no maps, nothing to trace yet; a height map loaded next makes it
    // a material like any other.
    void newEmptyMaterialHasNoMaps() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 16);
        QAction* empty = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->text() == "New &Empty Material")
                empty = a;
        if (empty == nullptr)
            QFAIL("File > New Empty Material is missing");
        QCOMPARE(empty->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
        empty->trigger();
        const DocumentState& s = w.document()->state();
        for (MapKind kind : kAllMapKinds)
            QVERIFY2(!s.hasMap(kind), mapTitle(kind).data());
        QVERIFY(!s.anyUnsaved());
        QVERIFY(w.document()->filePath().isEmpty());
        QVERIFY(!w.document()->isDirty());
        QCOMPARE(w.document()->undoStack()->count(), 0);
        QVERIFY(!s.canTrace(Technique::Pom));
        // A height map next: a material to trace.
        HeightField h(16, 16, 0.5f);
        const QString height = m_dir.filePath("flat_height.png");
        QVERIFY(writeImage(height.toStdString(), h.toImage(), {}).ok());
        QVERIFY(w.loadMap(MapKind::Height, height));
        QVERIFY(w.document()->state().canTrace(Technique::Pom));
    }

    void bakeOfAnOldSurfaceIsDiscarded() {
        DocumentState state = makeSampleState(ProceduralMap::Bricks, 16);
        BakeOutcome outcome;
        outcome.request = makeBakeRequest(state, BakeKind::Cone);
        outcome.cone = ConeMap(ConeKind::Conservative, 16, 16);
        const Result<DocumentState> baked = withBake(state, outcome);
        QVERIFY(baked);
        // The new state (an undo step) shares the maps with the old one and the bake: no copies.
        QVERIFY(baked->assets->height.texels.sharesWith(state.assets->height.texels));
        QVERIFY(baked->assets->albedo.pixels.sharesWith(state.assets->albedo.pixels));
        QVERIFY(baked->assets->cone.sqrtRatio.sharesWith(outcome.cone.sqrtRatio));
        DocumentState changed = state;
        auto assets = std::make_shared<MaterialAssets>(*state.assets);
        assets->height.at(3, 3) = 0.123f; // the copy's own texels now: the state's are unchanged
        QVERIFY(state.assets->height.at(3, 3) != 0.123f);
        changed.assets = assets;
        QVERIFY(!withBake(changed, outcome));
        changed = state;
        changed.material.wrap = WrapMode::Clamp;
        QVERIFY(!withBake(changed, outcome));
    }

    void wrapChangeBakesConesAgain() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 32);
        w.startBake(BakeKind::Cone);
        QTRY_VERIFY_WITH_TIMEOUT(!w.baker()->isBusy(), 60000);
        QVERIFY(w.document()->state().hasMap(MapKind::Cone));
        const int steps = w.document()->undoStack()->count();
        QComboBox* wrap = w.materialPanel()->findChild<QComboBox*>();
        QVERIFY(wrap);
        // The first combo of the panel is the height channel; find the wrap one by its items.
        for (QComboBox* c : w.materialPanel()->findChildren<QComboBox*>())
            if (c->findText("clamp") >= 0)
                wrap = c;
        wrap->setFocus();
        QTest::keyClicks(wrap, "clamp");
        QVERIFY(w.document()->material().wrap == WrapMode::Clamp);
        QVERIFY(!w.document()->state().hasMap(MapKind::Cone) || w.baker()->isBusy() ||
                w.document()->undoStack()->count() > steps + 1);
        QTRY_VERIFY_WITH_TIMEOUT(!w.baker()->isBusy(), 60000);
        QVERIFY(w.document()->state().hasMap(MapKind::Cone));
        QCOMPARE(w.document()->undoStack()->count(), steps + 2); // the wrap, the bake
    }

    void noGlDialogOffersSoftwareOrGoingOn() {
        GlProbe probe;
        probe.major = 3;
        probe.minor = 1;
        qunsetenv("LIBGL_ALWAYS_SOFTWARE");
        QStringList buttons;
        // Answer the dialog the way a user would: read it, then pick "Continue Without Preview".
        QTimer::singleShot(0, [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box)
                return;
            for (QAbstractButton* b : box->buttons())
                buttons << b->text();
            for (QAbstractButton* b : box->buttons())
                if (b->text().contains("Continue"))
                    b->click();
        });
        QCOMPARE(askAboutMissingGl(probe), GlChoice::ContinueWithoutPreview);
        QVERIFY(buttons.join(",").contains("Software Rendering"));
        QVERIFY(buttons.join(",").contains("Quit"));
    }

    void shortcutsSwitchLayoutAndViewport() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 16);
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_4));
        QCOMPARE(w.viewports()->layoutCount(), 4);
        QTest::keySequence(&w, QKeySequence(Qt::ALT | Qt::Key_3));
        QCOMPARE(w.viewports()->activeViewport(), 2);
        QCOMPARE(w.techniquePanel()->viewport(), 2);
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_1));
        QCOMPARE(w.viewports()->layoutCount(), 1);
        QCOMPARE(w.viewports()->activeViewport(), 0);
        QTest::keySequence(&w, QKeySequence(Qt::Key_L));
        QVERIFY(!w.viewports()->linked());
    }

    void everyControlExplainsItself() {
        MainWindow w(probeOpenGl().reason);
        for (SliderField* f : w.findChildren<SliderField*>()) {
            QVERIFY2(!f->slider()->toolTip().isEmpty(), qPrintable(f->objectName()));
            QVERIFY(!f->slider()->statusTip().isEmpty());
        }
        for (QAction* a : w.findChildren<QAction*>()) {
            if (!a->shortcut().isEmpty() && !a->text().isEmpty() && a->menu() == nullptr)
                QVERIFY2(!a->statusTip().isEmpty(), qPrintable(a->text()));
        }
    }

    void qualityRangeSetsTheLayers() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 16);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        RangeSlider* range = w.techniquePanel()->qualityRange();
        QCOMPARE(range->low(), 8 / 50.0);
        QCOMPARE(range->high(), 32 / 50.0);
        range->setFocus();
        QTest::keyClick(range, Qt::Key_Right);                    // low + 0.02: 9 layers
        QTest::keyClick(range, Qt::Key_Right, Qt::ShiftModifier); // high + 0.02: 33 layers
        QCOMPARE(w.document()->material().params.minLayers, 9);
        QCOMPARE(w.document()->material().params.maxLayers, 33);
        QCOMPARE(int(w.techniquePanel()->minLayers()->value()), 9);
        QCOMPARE(layersForQuality(0.5), 25);
        QCOMPARE(layersForQuality(0.0), 1);
    }

    void bakedNormalMapBecomesTheNormalSource() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Rivets, 32);
        QTest::mouseClick(w.mapsPanel()->row(MapKind::Normal)->bakeButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!w.baker()->isBusy(), 60000);
        const DocumentState& s = w.document()->state();
        QVERIFY(s.hasMap(MapKind::Normal));
        QVERIFY(s.material.normalSource == NormalSource::Map);
        QCOMPARE(s.assets->normal.width, 32);
        QVERIFY(w.mapsPanel()->row(MapKind::Normal)->sourceText().contains("not saved"));
    }

    void closingAsksBeforeLosingChanges() {
        MainWindow w(probeOpenGl().reason);
        w.newSample(ProceduralMap::Bricks, 16);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.document()->edit("tiling", [](DocumentState& s) { s.material.tiling = 5.0f; });
        QString asked;
        QTimer::singleShot(0, [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box)
                return;
            asked = box->text();
            box->button(QMessageBox::Cancel)->click();
        });
        QVERIFY(!w.close()); // cancelled: the window stays
        QVERIFY(asked.contains("not saved"));
        QVERIFY(w.isVisible());
        w.document()->undoStack()->undo();
        QVERIFY(w.close()); // nothing to lose: no question
    }

    void newHeightRebakesTheConeAViewportUses() {
        MainWindow w(probeOpenGl().reason);
        w.setInteractive(false);
        w.newSample(ProceduralMap::Bricks, 32);
        w.startBake(BakeKind::Cone);
        QTRY_VERIFY_WITH_TIMEOUT(!w.baker()->isBusy(), 60000);
        w.document()->edit("cone", [](DocumentState& s) {
            s.setView(0, {Technique::Cone, info(Technique::Cone).defaults});
        });
        Image flat(16, 16, 1);
        const std::string file = m_dir.filePath("flat_height.png").toStdString();
        QVERIFY(writeImage(file, flat, {PixelFormat::UInt16, false}));
        QVERIFY(w.loadMap(MapKind::Height, QString::fromStdString(file)));
        // The old cone map went with the old surface; a new one is baking for viewport 1.
        QVERIFY(w.baker()->isBusy() || w.document()->state().hasMap(MapKind::Cone));
        QTRY_VERIFY_WITH_TIMEOUT(!w.baker()->isBusy(), 60000);
        QVERIFY(w.document()->state().hasMap(MapKind::Cone));
        QCOMPARE(w.document()->state().assets->cone.width, 16);
    }

    void recentFilesNewestFirst() {
        RecentFiles recent;
        recent.clear();
        for (int i = 0; i < 12; ++i)
            recent.add(QStringLiteral("/tmp/m%1.json").arg(i));
        QCOMPARE(recent.files().size(), RecentFiles::kMaxFiles);
        QCOMPARE(recent.files().front(), QString("/tmp/m11.json"));
        recent.add("/tmp/m5.json");
        QCOMPARE(recent.files().front(), QString("/tmp/m5.json"));
        QCOMPARE(recent.files().count("/tmp/m5.json"), 1);
        RecentFiles again; // read back from the settings
        QCOMPARE(again.files(), recent.files());
    }
};

QTEST_MAIN(StudioOffscreenTest)
#include "StudioOffscreenTest.moc"

// Importing texture sets in the editor, as an artist opening their own folder would, on Qt's
// offscreen platform: a dropped set becomes a new material named after it with its relief read
// from the data and its normal map in use; two sets are never mixed; the summary flips the
// reading in one click and Enter keeps it; a normal-only folder is never merged into the open
// material and offers a derived height map; an unrecognised folder is refused with the report;
// the name field, "auto" green, a stale baked normal map and baking over a loaded one.

#include "StudioTestSupport.h"
#include "TextureSets.h"
#include "jobs/Baking.h"
#include "panels/ImportSummaryDialog.h"
#include "panels/MapRow.h"
#include "panels/MapsPanel.h"
#include "panels/MaterialPanel.h"
#include "parallax/io/AtomicWrite.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTimer>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;
using px::test::TextureSetSpec;
using px::test::writeTextureSet;

class StudioImportTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_settings;

private slots:
    void initTestCase() { isolateSettings(m_settings); }

    void droppedFolderBecomesANewMaterialReadFromTheData() {
        auto w = makeWindow();
        QVERIFY(w);
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "toy_box";
        spec.depth = true;
        spec.green = NormalGreen::DirectX;
        spec.albedoSuffix = false;
        const auto written = writeTextureSet(dir.path().toStdString(), spec);
        w->document()->edit("scale", [](DocumentState& s) { s.material.heightScale = 0.2f; });

        QVERIFY(dropFiles(w.get(), {dir.path()}));
        const DocumentState& s = w->document()->state();
        QCOMPARE(QString::fromStdString(s.material.name), QString("toy_box"));
        QVERIFY(w->document()->filePath().isEmpty()); // new: never saved
        QCOMPARE(w->document()->undoStack()->count(), 0);
        QCOMPARE(s.material.heightScale, Material{}.heightScale); // not the old material's
        QVERIFY(s.material.heightIsDepth);
        QCOMPARE(s.material.normalGreen, NormalGreen::DirectX);
        QCOMPARE(s.material.normalSource, NormalSource::Map);
        QCOMPARE(s.assets->albedo.width, spec.size); // the set's albedo, not the sample's
        QCOMPARE(QString::fromStdString(s.material.maps.albedo),
                 QString::fromStdString(written.albedoFile));
        QCOMPARE(w->materialPanel()->nameField()->text(), QString("toy_box"));
        QCOMPARE(w->windowTitle().contains("toy_box"), true);

        ImportSummaryDialog* summary = w->importSummary();
        QVERIFY(summary);
        QVERIFY(summary->decision().contains("depth map"));
        QVERIFY(summary->decision().contains("DirectX"));
        for (const char* file : {"toy_box_disp.png", "toy_box_normal.png", "toy_box.png"})
            QVERIFY2(summary->text().contains(file), file);

        // One click reads the height file the other way.
        const float before = s.assets->height.at(3, 5);
        summary->flipButton()->click();
        QVERIFY(!w->document()->state().material.heightIsDepth);
        QCOMPARE(w->document()->state().assets->height.at(3, 5), 1.0f - before);
        QVERIFY(w->materialPanel()->depthMap()->isChecked() == false);
    }

    void twoSetsAreNeverMixed() {
        auto w = makeWindow();
        QVERIFY(w);
        QTemporaryDir dir;
        TextureSetSpec a;
        a.stem = "bricks2";
        TextureSetSpec b;
        b.stem = "wall";
        b.seed = 2;
        writeTextureSet(dir.path().toStdString(), a);
        writeTextureSet(dir.path().toStdString(), b);
        const std::string sampleName = w->document()->material().name;

        QVERIFY(!w->importFolder(dir.path()));
        QVERIFY2(w->lastProblem().contains("holds 2 texture sets (bricks2, wall)"),
                 qPrintable(w->lastProblem()));
        QCOMPARE(w->document()->material().name, sampleName);

        QVERIFY(w->importFolder(dir.path(), "wall"));
        QCOMPARE(QString::fromStdString(w->document()->material().name), QString("wall"));
        QVERIFY(w->importSummary()->text().contains("Ignored: bricks2_disp.png (belongs to the "
                                                    "set bricks2)"));

        // Dropping one set's files imports that set.
        QVERIFY(dropFiles(w.get(),
                          {dir.filePath("bricks2_disp.png"), dir.filePath("bricks2_normal.png")}));
        QCOMPARE(QString::fromStdString(w->document()->material().name), QString("bricks2"));
        QVERIFY(w->document()->state().material.maps.albedo.empty());
    }

    void enterKeepsTheDataDecision() {
        auto w = makeWindow();
        QVERIFY(w);
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "slate";
        spec.depth = true;
        spec.seed = 6;
        writeTextureSet(dir.path().toStdString(), spec);
        QVERIFY(w->importFolder(dir.path()));
        QVERIFY(w->document()->state().material.heightIsDepth);
        ImportSummaryDialog* summary = w->importSummary();
        QVERIFY(summary);
        QVERIFY(!summary->flipButton()->isDefault() && !summary->flipButton()->autoDefault());
        summary->show();
        QVERIFY(QTest::qWaitForWindowExposed(summary));
        summary->flipButton()->setFocus(); // even with the flip focused, Enter is not a flip
        QTest::keyClick(summary, Qt::Key_Return);
        QVERIFY(w->document()->state().material.heightIsDepth);
        QVERIFY(!summary->isVisible());
    }

    // As an artist meets it: Import Folder in an interactive session, on a set whose height is
    // named _hgt (a name the old import did not know) beside an open material. A new material,
    // nothing of the open one kept, the report on screen, and Enter accepts the data's reading.
    void importFolderShowsTheReportAndEnterAccepts() {
        auto w = makeWindow(1, 64, true);
        QVERIFY(w);
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "stone";
        spec.heightSuffix = "_hgt";
        spec.depth = true;
        spec.green = NormalGreen::DirectX;
        spec.seed = 4;
        spec.size = 48;
        const auto written = writeTextureSet(dir.path().toStdString(), spec);
        const std::string openName = w->document()->material().name;
        const auto openAssets = w->document()->state().assets;

        QVERIFY(w->importFolder(dir.path()));
        const DocumentState& s = w->document()->state();
        QCOMPARE(QString::fromStdString(s.material.name), QString("stone"));
        QVERIFY(s.material.name != openName);
        QVERIFY(s.assets != openAssets);
        QCOMPARE(s.assets->height.width, spec.size); // the set's height, not the open one's
        QCOMPARE(QString::fromStdString(s.material.maps.height),
                 QString::fromStdString(written.heightFile));
        QVERIFY(s.material.heightIsDepth);
        QCOMPARE(s.material.normalGreen, NormalGreen::DirectX);
        QCOMPARE(w->document()->undoStack()->count(), 0); // a document of its own

        ImportSummaryDialog* summary = w->importSummary();
        QVERIFY(summary);
        QVERIFY(QTest::qWaitForWindowExposed(summary)); // shown without being asked
        for (const char* file : {"stone_hgt.png", "stone_normal.png", "stone_albedo.png"})
            QVERIFY2(summary->text().contains(file), qPrintable(summary->text()));
        QTest::keyClick(summary, Qt::Key_Return);
        QVERIFY(!w->importSummary() || !w->importSummary()->isVisible()); // accepted, closed
        QVERIFY(w->document()->state().material.heightIsDepth);
        QCOMPARE(w->document()->state().material.normalGreen, NormalGreen::DirectX);
        QCOMPARE(w->document()->undoStack()->count(), 0);
    }

    void aNormalOnlyFolderIsNeverMergedAndOffersAHeightMap() {
        auto w = makeWindow();
        QVERIFY(w);
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "stone01";
        spec.seed = 2;
        spec.green = NormalGreen::DirectX;
        const auto written = writeTextureSet(dir.path().toStdString(), spec);
        QVERIFY(QFile::remove(QString::fromStdString(written.heightFile)));
        const auto before = w->document()->state().assets;
        const std::string sampleName = w->document()->material().name;

        QVERIFY(!w->importFolder(dir.path())); // not yet: it asks
        auto* box = w->findChild<QMessageBox*>("derive-height");
        QVERIFY(box);
        QVERIFY(box->text().contains("stone01_normal.png"));
        // Nothing merged into the open material meanwhile.
        QCOMPARE(w->document()->material().name, sampleName);
        QVERIFY(w->document()->state().assets == before);

        QVERIFY(QTest::qWaitForWindowExposed(box));
        QTest::keyClick(box, Qt::Key_Return); // the default: make the height map
        const DocumentState& s = w->document()->state();
        QCOMPARE(QString::fromStdString(s.material.name), QString("stone01"));
        QVERIFY(w->document()->filePath().isEmpty());
        QCOMPARE(s.assets->height.width, spec.size);
        QVERIFY(s.isUnsaved(MapKind::Height)); // written beside the material when saved
        QCOMPARE(s.material.heightDerivedFrom, std::string("stone01_normal.png"));
        QCOMPARE(s.material.normalGreen, NormalGreen::DirectX);
        QCOMPARE(QString::fromStdString(s.material.maps.albedo),
                 QString::fromStdString(written.albedoFile));
        QVERIFY(w->importSummary());
        QVERIFY(w->importSummary()->decision().contains("derived from the normal map"));
        QVERIFY(!w->importSummary()->flipButton()->isEnabled());
    }

    // A height map derived from a normal map exists nowhere but here: the window says it is
    // unsaved, and importing another set asks first (Cancel keeps it, Discard replaces it).
    void anUnsavedDerivedHeightIsNotReplacedWithoutAsking() {
        auto w = makeWindow(1, 64, true);
        QVERIFY(w);
        QTemporaryDir normalOnly, full;
        TextureSetSpec spec;
        spec.stem = "stone01";
        spec.seed = 3;
        const auto written = writeTextureSet(normalOnly.path().toStdString(), spec);
        QVERIFY(QFile::remove(QString::fromStdString(written.heightFile)));
        TextureSetSpec wall;
        wall.stem = "wall";
        writeTextureSet(full.path().toStdString(), wall);

        QVERIFY(!w->importFolder(normalOnly.path()));
        auto* box = w->findChild<QMessageBox*>("derive-height");
        QVERIFY(box);
        QVERIFY(QTest::qWaitForWindowExposed(box));
        QTest::keyClick(box, Qt::Key_Return); // make the height map
        QCOMPARE(QString::fromStdString(w->document()->material().name), QString("stone01"));
        QVERIFY(w->document()->isDirty());
        QVERIFY(w->isWindowModified());

        QString asked;
        auto answer = [&asked](QMessageBox::StandardButton button) {
            auto* timer = new QTimer;
            timer->setInterval(20);
            QObject::connect(timer, &QTimer::timeout, [timer, button, &asked] {
                auto* question = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                if (!question)
                    return;
                asked = question->text();
                timer->stop();
                timer->deleteLater();
                question->button(button)->click();
            });
            timer->start();
        };
        answer(QMessageBox::Cancel);
        QVERIFY(!w->importFolder(full.path()));
        QVERIFY2(asked.contains("not saved"), qPrintable(asked));
        QCOMPARE(QString::fromStdString(w->document()->material().name), QString("stone01"));
        QVERIFY(w->document()->state().isUnsaved(MapKind::Height));

        asked.clear();
        answer(QMessageBox::Discard);
        QVERIFY(w->importFolder(full.path()));
        QVERIFY(!asked.isEmpty());
        QCOMPARE(QString::fromStdString(w->document()->material().name), QString("wall"));
        QVERIFY(!w->document()->isDirty()); // read from files: nothing to lose
        if (w->importSummary())
            w->importSummary()->close();
    }

    void anUnrecognisedFolderIsRefusedWithTheReport() {
        auto w = makeWindow();
        QVERIFY(w);
        QTemporaryDir dir;
        QVERIFY(writeTextFile(dir.filePath("IMG_0001.jpg").toStdString(), "x"));
        QVERIFY(writeTextFile(dir.filePath("notes.txt").toStdString(), "x"));
        const std::string name = w->document()->material().name;
        QVERIFY(!w->importFolder(dir.path()));
        QVERIFY2(w->lastProblem().contains("no texture set recognised"),
                 qPrintable(w->lastProblem()));
        QVERIFY(w->lastProblem().contains("IMG_0001.jpg: no map tag"));
        QVERIFY(w->lastProblem().contains("notes.txt: not an image file"));
        QCOMPARE(w->document()->material().name, name);
        QCOMPARE(w->document()->undoStack()->count(), 0);
    }

    void aSingleDroppedMapAddsToTheMaterial() {
        auto w = makeWindow();
        QVERIFY(w);
        QTemporaryDir dir;
        const auto set = writeTextureSet(dir.path().toStdString(), TextureSetSpec{});
        const std::string name = w->document()->material().name;
        QVERIFY(dropFiles(w.get(), {QString::fromStdString(set.normalFile)}));
        QCOMPARE(w->document()->material().name, name);
        QVERIFY(w->document()->state().hasMap(MapKind::Normal));
        // A loaded normal map is used.
        QCOMPARE(w->document()->material().normalSource, NormalSource::Map);
        // A packed map alone is not loaded as a height map.
        const std::string packed = dir.filePath("rock_arm.png").toStdString();
        QVERIFY(
            QFile::copy(QString::fromStdString(set.albedoFile), QString::fromStdString(packed)));
        const int steps = w->document()->undoStack()->count();
        QVERIFY(dropFiles(w.get(), {QString::fromStdString(packed)}));
        QVERIFY2(w->lastProblem().contains("rock_arm.png: ORM map by its name; import its set's "
                                           "folder to use it."),
                 qPrintable(w->lastProblem()));
        QCOMPARE(w->document()->undoStack()->count(), steps);
    }

    void nameFieldRenamesUndoably() {
        auto w = makeWindow();
        QVERIFY(w);
        QLineEdit* field = w->materialPanel()->nameField();
        field->setText("mossy stones");
        emit field->editingFinished();
        QCOMPARE(QString::fromStdString(w->document()->material().name), QString("mossy stones"));
        QVERIFY(w->windowTitle().contains("mossy stones"));
        w->document()->undoStack()->undo();
        QCOMPARE(field->text(), QString("bricks"));
    }

    void autoGreenIsToldFromTheHeightMap() {
        auto w = makeWindow();
        QVERIFY(w);
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.seed = 4;
        writeTextureSet(dir.path().toStdString(), spec);
        QVERIFY(w->importFolder(dir.path()));
        QComboBox* green = w->materialPanel()->normalGreen();
        green->setCurrentText("directx");
        QCOMPARE(w->document()->material().normalGreen, NormalGreen::DirectX);
        green->setCurrentText("auto");
        QCOMPARE(w->document()->material().normalGreen, NormalGreen::OpenGL);
        QCOMPARE(green->currentText(), QString("opengl"));
    }

    void bakingOverALoadedNormalMapAsksAndAStaleBakeSaysSo() {
        auto w = makeWindow();
        QVERIFY(w);
        QTemporaryDir dir;
        writeTextureSet(dir.path().toStdString(), TextureSetSpec{});
        QVERIFY(w->importFolder(dir.path()));
        w->startBake(BakeKind::Normal);
        auto* box = w->findChild<QMessageBox*>("confirm-normal-bake");
        QVERIFY(box);
        QVERIFY(!w->baker()->isBusy()); // nothing until the user says so
        QVERIFY(box->text().contains("rock_normal.png"));
        QSignalSpy finished(w->baker(), &BakeRunner::finished);
        QPushButton* bake = nullptr;
        for (QAbstractButton* b : box->buttons())
            if (b->text() == "Bake")
                bake = qobject_cast<QPushButton*>(b);
        QVERIFY(bake);
        bake->click();
        QVERIFY(finished.wait(30000));
        const DocumentState& s = w->document()->state();
        QVERIFY(s.isUnsaved(MapKind::Normal));
        QVERIFY(s.normalBake);
        MapRow* row = w->mapsPanel()->row(MapKind::Normal);
        QVERIFY(row->warningText().isEmpty());

        w->document()->edit("scale", [](DocumentState& st) { st.material.heightScale = 0.1f; });
        QVERIFY2(row->warningText().contains("baked at height scale 0.05, now 0.1"),
                 qPrintable(row->warningText()));
        // A baked map over a baked map needs no question.
        w->document()->edit("scale", [](DocumentState& st) { st.material.heightScale = 0.05f; });
        QVERIFY(row->warningText().isEmpty());
        w->startBake(BakeKind::Normal);
        QVERIFY(w->baker()->isBusy());
        QVERIFY(finished.wait(30000));
    }
};

QTEST_MAIN(StudioImportTest)
#include "StudioImportTest.moc"

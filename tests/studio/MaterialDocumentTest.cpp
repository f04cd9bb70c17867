// The document model: every edit is one undo step, slider drags merge, undo restores the previous
// state exactly, and only saved settings make the document dirty.

#include "model/MaterialDocument.h"

#include "model/SampleMaterial.h"

#include <QSignalSpy>
#include <QTest>

using namespace px;
using namespace px::studio;

class MaterialDocumentTest : public QObject {
    Q_OBJECT
private slots:
    void editIsOneUndoStep() {
        MaterialDocument doc;
        doc.reset(makeSampleState(ProceduralMap::Bricks, 32), {});
        const float before = doc.material().heightScale;
        doc.edit("Height scale", [](DocumentState& s) { s.material.heightScale = 0.2f; });
        QCOMPARE(doc.material().heightScale, 0.2f);
        QCOMPARE(doc.undoStack()->count(), 1);
        doc.undoStack()->undo();
        QCOMPARE(doc.material().heightScale, before);
        doc.undoStack()->redo();
        QCOMPARE(doc.material().heightScale, 0.2f);
    }

    void dragMergesUntilEndMerge() {
        MaterialDocument doc;
        doc.reset(makeSampleState(ProceduralMap::Bricks, 32), {});
        for (int i = 1; i <= 10; ++i)
            doc.edit(
                "Height scale", [i](DocumentState& s) { s.material.heightScale = 0.01f * i; },
                "heightScale");
        QCOMPARE(doc.undoStack()->count(), 1);
        doc.endMerge();
        doc.edit(
            "Height scale", [](DocumentState& s) { s.material.heightScale = 0.5f; }, "heightScale");
        QCOMPARE(doc.undoStack()->count(), 2);
        doc.undoStack()->undo();
        QCOMPARE(doc.material().heightScale, 0.1f);
        doc.undoStack()->undo();
        QCOMPARE(doc.material().heightScale, 0.06f);
    }

    void editThatChangesNothingPushesNothing() {
        MaterialDocument doc;
        doc.reset(makeSampleState(ProceduralMap::Bricks, 32), {});
        doc.edit("Nothing", [](DocumentState&) {});
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void dirtyFollowsSavedSettingsOnly() {
        MaterialDocument doc;
        doc.reset(makeSampleState(ProceduralMap::Bricks, 32), {});
        QSignalSpy dirty(&doc, &MaterialDocument::dirtyChanged);
        QVERIFY(!doc.isDirty());
        // Another viewport's technique is a view setting: not a change to the file, not history.
        doc.edit("Viewport 3", [](DocumentState& s) {
            s.setView(2, {Technique::Steep, info(Technique::Steep).defaults});
        });
        QVERIFY(!doc.isDirty());
        QCOMPARE(doc.undoStack()->count(), 0);
        QCOMPARE(doc.state().view(2).technique, Technique::Steep);
        doc.edit("Shadow",
                 [](DocumentState& s) { s.material.selfShadow = !s.material.selfShadow; });
        QVERIFY(doc.isDirty());
        QCOMPARE(dirty.count(), 1);
        doc.undoStack()->undo();
        QVERIFY(!doc.isDirty());
        QCOMPARE(dirty.count(), 2);
        QCOMPARE(doc.state().view(2).technique, Technique::Steep); // undo leaves views alone
    }

    void viewportOneIsTheMaterialsTechnique() {
        DocumentState state = makeSampleState(ProceduralMap::Bricks, 32);
        TraceParams params = info(Technique::Steep).defaults;
        params.binarySteps = 9;
        state.setView(0, {Technique::Steep, params});
        QCOMPARE(state.material.technique, Technique::Steep);
        QCOMPARE(state.material.params.binarySteps, 9);
        QCOMPARE(state.view(0).technique, Technique::Steep);
        QVERIFY(state.view(1).technique != Technique::Steep);
    }

    void changeFlagsSayWhatChanged() {
        MaterialDocument doc;
        doc.reset(makeSampleState(ProceduralMap::Bricks, 32), {});
        QSignalSpy changed(&doc, &MaterialDocument::changed);
        doc.edit("Tiling", [](DocumentState& s) { s.material.tiling = 3.0f; });
        QCOMPARE(changed.count(), 1);
        auto what = changed.takeFirst().at(0).value<MaterialDocument::Changes>();
        QVERIFY(what.testFlag(MaterialDocument::MaterialChanged));
        QVERIFY(!what.testFlag(MaterialDocument::MapsChanged));
        doc.edit("Clear albedo", [](DocumentState& s) {
            auto assets = std::make_shared<MaterialAssets>(*s.assets);
            assets->albedo = {};
            s.assets = assets;
        });
        what = changed.takeFirst().at(0).value<MaterialDocument::Changes>();
        QVERIFY(what.testFlag(MaterialDocument::MapsChanged));
        QVERIFY(!what.testFlag(MaterialDocument::MaterialChanged));
    }

    void conesNeedAConeMap() {
        DocumentState state = makeSampleState(ProceduralMap::Bricks, 32);
        QVERIFY(state.canTrace(Technique::Pom));
        QVERIFY(state.canTrace(Technique::Pyramid));
        QVERIFY(!state.canTrace(Technique::Cone));
        QVERIFY(!state.canTrace(Technique::RelaxedCone));
        auto assets = std::make_shared<MaterialAssets>(*state.assets);
        assets->cone = ConeMap(ConeKind::Conservative, 32, 32);
        state.assets = assets;
        QVERIFY(state.canTrace(Technique::Cone));
    }
};

QTEST_MAIN(MaterialDocumentTest)
#include "MaterialDocumentTest.moc"

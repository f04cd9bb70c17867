// Undo as an artist uses it: Ctrl+Z works while a spin box has focus, a save followed by undo and
// redo leaves the saved maps saved, and viewports' techniques stay out of the material's history.

#include "StudioTestSupport.h"
#include "panels/MaterialPanel.h"
#include "widgets/SliderField.h"

#include <QDoubleSpinBox>
#include <QUndoStack>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

class UndoTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { isolateSettings(m_dir); }

    void ctrlZWorksWhileASpinBoxHasFocus() {
        auto w = makeWindow();
        QVERIFY(w);
        const float before = w->document()->material().heightScale;
        QDoubleSpinBox* field = w->materialPanel()->heightScale()->field();
        field->setFocus();
        QVERIFY(QTest::qWaitFor([&] { return field->hasFocus(); }));
        field->selectAll();
        QTest::keyClicks(field, "0.125");
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(w->document()->material().heightScale, 0.125f);
        const int steps = w->document()->undoStack()->count();
        QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
        // The document's undo, not the field's own text undo (which would be a new edit).
        QCOMPARE(w->document()->undoStack()->count(), steps);
        QCOMPARE(w->document()->undoStack()->index(), steps - 1);
        QCOMPARE(w->document()->material().heightScale, before);
        QTest::keyClick(field, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(w->document()->material().heightScale, 0.125f);
        // Both redo keys work (the platform's Redo is one of them, listed once).
        QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(w->document()->material().heightScale, before);
        QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(w->document()->material().heightScale, 0.125f);
    }

    void saveThenUndoAndRedoKeepsMapsSaved() {
        auto w = makeWindow();
        QVERIFY(w);
        MaterialDocument* doc = w->document();
        QVERIFY(doc->state().isUnsaved(MapKind::Height)); // the sample's maps are made here
        doc->edit("scale", [](DocumentState& s) { s.material.heightScale = 0.07f; });
        QVERIFY(w->saveTo(m_dir.filePath("undo.json")));
        QVERIFY(!doc->isDirty());
        doc->undoStack()->undo();
        for (MapKind kind : kAllMapKinds)
            QVERIFY2(!doc->state().isUnsaved(kind), mapKey(kind).data());
        QCOMPARE(QFileInfo(QString::fromStdString(doc->material().maps.height)).fileName(),
                 QString("undo_height.png"));
        QVERIFY(doc->isDirty()); // the scale differs from the file
        doc->undoStack()->redo();
        for (MapKind kind : kAllMapKinds)
            QVERIFY2(!doc->state().isUnsaved(kind), mapKey(kind).data());
        QVERIFY(!doc->isDirty());
    }

    void viewportTechniquesStayOutOfTheHistory() {
        auto w = makeWindow(4);
        QVERIFY(w);
        MaterialDocument* doc = w->document();
        const float scale = doc->material().heightScale;
        doc->edit("scale", [](DocumentState& s) { s.material.heightScale = 0.09f; });
        const int steps = doc->undoStack()->count();
        doc->edit("viewport 3", [](DocumentState& s) {
            s.setView(2, {Technique::Secant, info(Technique::Secant).defaults});
        });
        QCOMPARE(doc->undoStack()->count(), steps);
        QCOMPARE(doc->state().view(2).technique, Technique::Secant);
        doc->undoStack()->undo();
        QCOMPARE(doc->material().heightScale, scale);
        QCOMPARE(doc->state().view(2).technique, Technique::Secant);
    }
};

QTEST_MAIN(UndoTest)
#include "UndoTest.moc"

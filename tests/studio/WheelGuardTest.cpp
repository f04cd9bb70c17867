// The mouse wheel over the editor's panels scrolls them: no combo box, spin box or slider it passes
// over changes unless it has the keyboard focus (widgets/WheelGuard.h).

#include "widgets/WheelGuard.h"

#include "StudioTestSupport.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDockWidget>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QSpontaneKeyEvent>
#include <QUndoStack>
#include <QWheelEvent>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

namespace {

// A notch of the wheel over `widget`'s centre, as the window system delivers it (spontaneous:
// Qt gives an unfocused field's refused wheel to its parents only then).
void wheel(QWidget* widget, int notches) {
    const QPointF at(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent event(at, widget->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    // As QTest delivers input: notify() keeps the flag, sendEvent() would clear it.
    QSpontaneKeyEvent::setSpontaneous(&event);
    qApp->notify(widget, &event);
}

// What a field shows: its index, text or position.
QString valueOf(QWidget* field) {
    if (auto* combo = qobject_cast<QComboBox*>(field))
        return QString::number(combo->currentIndex());
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(field))
        return spin->text();
    return QString::number(qobject_cast<QAbstractSlider*>(field)->value());
}

QScrollArea* dockScrollArea(MainWindow& window, const char* dock) {
    auto* d = window.findChild<QDockWidget*>(QString::fromLatin1(dock));
    return d ? qobject_cast<QScrollArea*>(d->widget()) : nullptr;
}

} // namespace

class WheelGuardTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { isolateSettings(m_dir); }

    // Every field of the scrolling panels, wheeled over up and down without the focus: none
    // changes, the material's history gains no step.
    void unfocusedFieldsIgnoreTheWheel() {
        auto w = makeWindow();
        QVERIFY(w);
        int tried = 0;
        for (const char* dock : {"ParametersDock", "MapsDock"}) {
            QScrollArea* area = dockScrollArea(*w, dock);
            QVERIFY2(area, dock);
            w->findChild<QDockWidget*>(QString::fromLatin1(dock))->raise();
            for (QWidget* field : area->widget()->findChildren<QWidget*>()) {
                if (!WheelGuard::guards(field) || !field->isVisible() || !field->isEnabled())
                    continue;
                w->setFocus(); // none of the fields
                QVERIFY(!field->hasFocus());
                const QString before = valueOf(field);
                const int steps = w->document()->undoStack()->count();
                for (int notches : {-1, -1, 1, 1, 1}) {
                    wheel(field, notches);
                    QCOMPARE(valueOf(field), before);
                }
                QCOMPARE(w->document()->undoStack()->count(), steps);
                QVERIFY2(!field->hasFocus(), qPrintable(field->objectName()));
                ++tried;
            }
        }
        // The material's, technique's and view's combo boxes, spin boxes and sliders.
        QVERIFY2(tried >= 12, qPrintable(QString::number(tried)));
    }

    // The wheel a field refuses scrolls the panel it is in.
    void thePanelScrollsUnderTheWheel() {
        auto w = makeWindow();
        QVERIFY(w);
        QScrollArea* area = dockScrollArea(*w, "ParametersDock");
        QVERIFY(area);
        QScrollBar* bar = area->verticalScrollBar();
        QVERIFY2(bar->maximum() > 0, "the panel is taller than its dock");
        auto* combo = area->widget()->findChild<QComboBox*>();
        QVERIFY(combo && combo->isVisible());
        w->setFocus();
        const int top = bar->value();
        wheel(combo, -1);
        QVERIFY(bar->value() > top);
    }

    // Clicked or tabbed to, a field takes the wheel as ever.
    void aFocusedFieldTakesTheWheel() {
        auto w = makeWindow();
        QVERIFY(w);
        QScrollArea* area = dockScrollArea(*w, "ParametersDock");
        QVERIFY(area);
        QAbstractSpinBox* spin = nullptr;
        for (auto* s : area->widget()->findChildren<QAbstractSpinBox*>())
            if (s->isVisible() && s->isEnabled() && !spin)
                spin = s;
        QVERIFY(spin);
        QCOMPARE(spin->focusPolicy(), Qt::StrongFocus); // a wheel never focuses it
        spin->setFocus();
        QVERIFY(QTest::qWaitFor([&] { return spin->hasFocus(); }));
        const QString before = valueOf(spin);
        wheel(spin, 1);
        if (valueOf(spin) == before) // at its maximum
            wheel(spin, -1);
        QVERIFY(valueOf(spin) != before);
    }
};

QTEST_MAIN(WheelGuardTest)
#include "WheelGuardTest.moc"

#include "widgets/WheelGuard.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDial>
#include <QEvent>
#include <QSlider>
#include <QWidget>

namespace px::studio {

namespace {

// A field Qt gives the focus to when wheeled over (Qt::WheelFocus, the default of combo and spin
// boxes) would have it before the wheel arrives: such fields take the focus by click or Tab only.
void takeFocusByClickOrTab(QWidget* field) {
    if (field->focusPolicy() == Qt::WheelFocus)
        field->setFocusPolicy(Qt::StrongFocus);
}

} // namespace

WheelGuard::WheelGuard(QObject* parent) : QObject(parent) {
    // Fields made before the guard: new ones are seen as they are polished (before they show).
    for (QWidget* widget : QApplication::allWidgets())
        if (guards(widget))
            takeFocusByClickOrTab(widget);
    qApp->installEventFilter(this);
}

bool WheelGuard::guards(const QObject* widget) {
    // Not scroll bars: they are what the refused wheel goes to.
    return qobject_cast<const QComboBox*>(widget) ||
           qobject_cast<const QAbstractSpinBox*>(widget) || qobject_cast<const QSlider*>(widget) ||
           qobject_cast<const QDial*>(widget);
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Polish && guards(watched)) {
        takeFocusByClickOrTab(static_cast<QWidget*>(watched));
    } else if (event->type() == QEvent::Wheel && guards(watched)) {
        auto* field = static_cast<QWidget*>(watched);
        if (!field->hasFocus()) {
            // Refused, not eaten: an ignored wheel goes on to the parents (the panel scrolls).
            event->ignore();
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace px::studio

#pragma once
// The mouse wheel over a panel scrolls the panel: a combo box, spin box or slider takes the wheel
// only while it has the keyboard focus (clicked or tabbed to). Qt hands the wheel to whichever
// such field is under the pointer, so scrolling the Parameters panel changed every field it
// passed over (a Normals setting changed while scrolling: two undo steps). Installed on the
// application, it covers every field of every window, made now or later; the wheel it refuses goes
// on to the field's parents (a panel's scroll area).

#include <QObject>

class QWidget;

namespace px::studio {

class WheelGuard : public QObject {
    Q_OBJECT
public:
    explicit WheelGuard(QObject* parent = nullptr); // installs itself on the application
    // Whether `widget` is a field the guard keeps the unfocused wheel from.
    static bool guards(const QObject* widget);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
};

} // namespace px::studio

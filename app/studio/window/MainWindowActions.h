#pragma once
// The main window's actions that more than one of its files reach (private to MainWindow).

#include "window/MainWindow.h"

#include <QList>

class QAction;
class QActionGroup;

namespace px::studio {

struct MainWindow::Actions {
    QAction* undo = nullptr;
    QAction* redo = nullptr;
    QAction* link = nullptr;
    QAction* heatMap = nullptr;
    QAction* wipe = nullptr;
    QActionGroup* layout = nullptr;
    QList<QAction*> layouts;
};

} // namespace px::studio

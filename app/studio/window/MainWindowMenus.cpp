// MainWindow: actions, menus and shortcuts.

#include "model/MaterialDocument.h"
#include "model/SampleMaterial.h"
#include "panels/ComparePanel.h"
#include "preview/Viewport.h"
#include "preview/ViewportGrid.h"
#include "window/BakeDeviceMenu.h"
#include "window/MainWindow.h"
#include "window/MainWindowActions.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSet>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>

namespace px::studio {

namespace {

QAction* action(QObject* parent, const QString& text, const QKeySequence& key, const QString& tip) {
    auto* a = new QAction(text, parent);
    if (!key.isEmpty())
        a->setShortcut(key);
    a->setStatusTip(tip);
    a->setToolTip(key.isEmpty() ? text
                                : QStringLiteral("%1 (%2)").arg(
                                      text, key.toString(QKeySequence::NativeText)));
    return a;
}

} // namespace

void MainWindow::createActions() {
    m_actions = std::make_unique<Actions>();
    m_actions->undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    m_actions->undo->setShortcut(QKeySequence::Undo);
    m_actions->redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    // Ctrl+Y and Ctrl+Shift+Z on every platform, each once: where the platform's Redo already is
    // Ctrl+Y, listing it twice made the shortcut ambiguous and neither fired.
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    for (const QKeySequence& key :
         {QKeySequence(Qt::CTRL | Qt::Key_Y), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)}) {
        if (!redoKeys.contains(key))
            redoKeys << key;
    }
    m_actions->redo->setShortcuts(redoKeys);
    m_actions->undo->setStatusTip(tr("Undo the last edit; the History panel lists every step."));
    m_actions->redo->setStatusTip(tr("Redo the edit just undone."));
}

void MainWindow::createMenus() {
    // File
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* empty =
        action(this, tr("New &Empty Material"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N),
               tr("A new material with no maps: load or drop its height map next."));
    connect(empty, &QAction::triggered, this, &MainWindow::newEmptyMaterial);
    file->addAction(empty);
    QMenu* samples = file->addMenu(tr("&New Sample"));
    for (ProceduralMap kind : sampleKinds()) {
        const QString name =
            QString::fromUtf8(proceduralMapNames()[static_cast<std::size_t>(kind)].data());
        QAction* a = samples->addAction(name.left(1).toUpper() + name.mid(1));
        a->setStatusTip(
            tr("A new material on the built-in %1 maps, made by the project.").arg(name));
        if (kind == ProceduralMap::Bricks)
            a->setShortcut(QKeySequence::New);
        connect(a, &QAction::triggered, this, [this, kind] { newSample(kind); });
    }
    QAction* open = action(this, tr("&Open…"), QKeySequence::Open, tr("Open a material (.json)."));
    connect(open, &QAction::triggered, this, &MainWindow::openDialog);
    file->addAction(open);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    file->addSeparator();
    QAction* save = action(this, tr("&Save"), QKeySequence::Save,
                           tr("Save the material and the maps made here beside it."));
    connect(save, &QAction::triggered, this, &MainWindow::save);
    QAction* saveAs = action(this, tr("Save &As…"), QKeySequence::SaveAs,
                             tr("Save the material under another name or folder."));
    connect(saveAs, &QAction::triggered, this, &MainWindow::saveAs);
    file->addActions({save, saveAs});
    file->addSeparator();
    QMenu* importMap = file->addMenu(tr("&Load Map"));
    for (MapKind kind : kAllMapKinds) {
        QAction* a =
            importMap->addAction(QString::fromUtf8(mapTitle(kind).data()) + QStringLiteral("…"));
        a->setStatusTip(tr("Load the %1 map from an image file.")
                            .arg(QString::fromUtf8(mapTitle(kind).data()).toLower()));
        if (kind == MapKind::Height)
            a->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
        connect(a, &QAction::triggered, this, [this, kind] { importMapDialog(kind); });
    }
    QAction* folder =
        action(this, tr("Import &Folder…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_I),
               tr("Load every map of a folder, recognised by suffix (_albedo, "
                  "_height, _disp, _normal, ...)."));
    connect(folder, &QAction::triggered, this, &MainWindow::importFolderDialog);
    QAction* exportAction =
        action(this, tr("&Export…"), QKeySequence(Qt::CTRL | Qt::Key_E),
               tr("Export for the project's renderer, glTF, Godot, Unreal or Unity."));
    connect(exportAction, &QAction::triggered, this, &MainWindow::exportDialog);
    QAction* mesh = action(this, tr("Load &Mesh…"), QKeySequence(Qt::CTRL | Qt::Key_M),
                           tr("Show the material on an OBJ or glTF mesh (.obj, .gltf, .glb)."));
    connect(mesh, &QAction::triggered, this, &MainWindow::loadMeshDialog);
    QAction* viewPicture =
        action(this, tr("Save &View as PNG…"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S),
               tr("Render the active view at any size into a PNG."));
    connect(viewPicture, &QAction::triggered, this,
            [this] { picturesDialog(PictureKind::ActiveView); });
    QAction* allPicture = action(this, tr("Save &All Views as PNG…"), QKeySequence(),
                                 tr("Render every shown view, side by side, into one PNG."));
    connect(allPicture, &QAction::triggered, this,
            [this] { picturesDialog(PictureKind::AllViews); });
    QAction* turntable = action(this, tr("Save &Turntable…"), QKeySequence(),
                                tr("Render the active view orbiting once, N numbered PNGs."));
    connect(turntable, &QAction::triggered, this,
            [this] { picturesDialog(PictureKind::Turntable); });
    file->addActions({folder, mesh, exportAction});
    file->addSeparator();
    file->addActions({viewPicture, allPicture, turntable});
    file->addSeparator();
    QAction* quit = action(this, tr("&Quit"), QKeySequence::Quit, tr("Close Parallax Studio."));
    connect(quit, &QAction::triggered, this, &QWidget::close);
    file->addAction(quit);

    // Edit
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addActions({m_actions->undo, m_actions->redo});

    // View
    QMenu* view = menuBar()->addMenu(tr("&View"));
    m_actions->layout = new QActionGroup(this);
    for (int count : {1, 2, 4}) {
        QAction* a =
            action(this, tr("%n Viewport(s)", nullptr, count),
                   QKeySequence(QKeyCombination(Qt::ControlModifier, Qt::Key(Qt::Key_0 + count))),
                   tr("Show %n viewport(s) side by side.", nullptr, count));
        a->setCheckable(true);
        a->setData(count);
        a->setChecked(count == m_viewports->layoutCount());
        m_actions->layout->addAction(a);
        m_actions->layouts << a;
        view->addAction(a);
        connect(a, &QAction::triggered, this,
                [this, count] { m_viewports->setLayoutCount(count); });
    }
    connect(m_viewports, &ViewportGrid::layoutCountChanged, this, [this](int count) {
        for (QAction* a : m_actions->layouts)
            a->setChecked(a->data().toInt() == count);
    });
    view->addSeparator();
    for (int i = 0; i < 4; ++i) {
        QAction* a = action(this, tr("Activate Viewport %1").arg(i + 1),
                            QKeySequence(QKeyCombination(Qt::AltModifier, Qt::Key(Qt::Key_1 + i))),
                            tr("Make viewport %1 the one the technique panel edits.").arg(i + 1));
        connect(a, &QAction::triggered, this, [this, i] {
            if (i >= m_viewports->layoutCount())
                m_viewports->setLayoutCount(i >= 2 ? 4 : 2);
            m_viewports->setActiveViewport(i);
        });
        view->addAction(a);
    }
    view->addSeparator();
    m_actions->link = action(this, tr("&Link Viewports"), QKeySequence(Qt::Key_L),
                             tr("Share camera and light between the viewports."));
    m_actions->link->setCheckable(true);
    m_actions->link->setChecked(m_viewports->linked());
    connect(m_actions->link, &QAction::toggled, m_viewports, &ViewportGrid::setLinked);
    connect(m_viewports, &ViewportGrid::linkedChanged, m_actions->link, &QAction::setChecked);
    m_actions->heatMap = action(this, tr("Error &Heat Map"), QKeySequence(Qt::Key_H),
                                tr("Show the active viewport's technique error: its hit against "
                                   "the exact hit on the mip level it reads."));
    connect(m_actions->heatMap, &QAction::triggered, this, [this] {
        m_viewports->viewport(m_viewports->activeViewport())->heatMapButton()->toggle();
    });
    // The heat map of the filtering's error (the mip level against level 0), Shift+H.
    QAction* filteringHeat =
        action(this, tr("&Filtering Error Heat Map"), QKeySequence(Qt::SHIFT | Qt::Key_H),
               tr("Show the active viewport's filtering error: the exact hit on the mip level "
                  "its technique reads against the exact hit on level 0."));
    connect(filteringHeat, &QAction::triggered, this, [this] {
        Viewport* v = m_viewports->viewport(m_viewports->activeViewport());
        v->heatModeAction(HeatMode::Filtering)->trigger();
    });
    m_actions->wipe = action(this, tr("A/B &Wipe"), QKeySequence(Qt::Key_W),
                             tr("Split the active viewport between two techniques."));
    connect(m_actions->wipe, &QAction::triggered, this, [this] {
        m_viewports->viewport(m_viewports->activeViewport())->wipeButton()->toggle();
    });
    QAction* reset = action(this, tr("&Reset Camera"), QKeySequence(Qt::Key_Home),
                            tr("Back to the default orbit."));
    connect(reset, &QAction::triggered, m_viewports, &ViewportGrid::resetCameras);
    view->addActions({m_actions->link, m_actions->heatMap, filteringHeat, m_actions->wipe, reset});
    view->addSeparator();
    QAction* fullScreen = action(this, tr("&Full Screen"), QKeySequence::FullScreen,
                                 tr("The window over the whole screen, and back."));
    fullScreen->setCheckable(true);
    connect(fullScreen, &QAction::toggled, this,
            [this](bool on) { on ? showFullScreen() : showNormal(); });
    view->addAction(fullScreen);
    m_panelsMenu = view->addMenu(tr("&Panels"));
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        m_panelsMenu->addAction(dock->toggleViewAction());

    // Bake
    QMenu* bake = menuBar()->addMenu(tr("&Bake"));
    const std::pair<BakeKind, QKeySequence> bakes[] = {
        {BakeKind::Normal, QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_N)},
        {BakeKind::Cone, QKeySequence(Qt::CTRL | Qt::Key_B)},
        {BakeKind::RelaxedCone, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B)},
        {BakeKind::Occlusion, QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_O)},
        {BakeKind::BentNormal, QKeySequence()}};
    for (const auto& [kind, key] : bakes) {
        const QString title = bakeTitle(kind);
        QAction* a = action(this, tr("Bake %1").arg(title.left(1).toUpper() + title.mid(1)), key,
                            tr("Bake a %1 from the height map in the background.").arg(title));
        connect(a, &QAction::triggered, this, [this, k = kind] { startBake(k); });
        bake->addAction(a);
    }
    QAction* fromMesh = action(this, tr("From &Mesh…"), QKeySequence(),
                               tr("Bake height, normal and occlusion maps from a sculpted tile "
                                  "into a new material."));
    connect(fromMesh, &QAction::triggered, this, &MainWindow::bakeFromMeshDialog);
    bake->addAction(fromMesh);
    QAction* cancel = action(this, tr("&Cancel Bake"), QKeySequence(Qt::Key_Escape),
                             tr("Stop the running bake; nothing changes."));
    connect(cancel, &QAction::triggered, m_baker, &BakeRunner::cancel);
    bake->addSeparator();
    bake->addAction(cancel);
    bake->addMenu(makeBakeDeviceMenu(m_baker, bake));

    // Compare
    QMenu* compare = menuBar()->addMenu(tr("&Compare"));
    QAction* run = action(this, tr("&Run Comparison"), QKeySequence(Qt::CTRL | Qt::Key_R),
                          tr("Measure every technique's error against its cost on this material."));
    connect(run, &QAction::triggered, this, [this] {
        if (auto* dock = qobject_cast<QDockWidget*>(m_comparePanel->parentWidget())) {
            dock->show();
            dock->raise();
        }
        m_comparePanel->run();
    });
    compare->addAction(run);

    // Help
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* shortcuts = action(this, tr("&Keyboard and Mouse"), QKeySequence::HelpContents,
                                tr("Every shortcut and mouse gesture."));
    connect(shortcuts, &QAction::triggered, this, &MainWindow::showShortcuts);
    help->addAction(shortcuts);
    help->addAction(tr("&About Parallax Studio"), this, [this] {
        QMessageBox::about(this, tr("About Parallax Studio"),
                           tr("<b>Parallax Studio</b><p>Tune parallax materials, bake their maps, "
                              "and see which technique is accurate enough at what cost.</p>"));
    });
    addActions({m_actions->undo, m_actions->redo});

    // The toolbar: the actions used most, with icons (SVG, sharp at any pixel ratio).
    auto icon = [](const char* name) { return QIcon(QStringLiteral(":/icons/%1.svg").arg(name)); };
    open->setIcon(icon("open"));
    save->setIcon(icon("save"));
    m_actions->undo->setIcon(icon("undo"));
    m_actions->redo->setIcon(icon("redo"));
    m_actions->link->setIcon(icon("link"));
    m_actions->heatMap->setIcon(icon("heatmap"));
    m_actions->wipe->setIcon(icon("wipe"));
    run->setIcon(icon("compare"));
    const char* layoutIcons[] = {"layout-1", "layout-2", "layout-4"};
    for (int i = 0; i < m_actions->layouts.size(); ++i)
        m_actions->layouts[i]->setIcon(icon(layoutIcons[i]));
    QToolBar* bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("MainToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonIconOnly);
    bar->addActions({open, save});
    bar->addSeparator();
    bar->addActions({m_actions->undo, m_actions->redo});
    bar->addSeparator();
    bar->addActions(m_actions->layouts);
    bar->addAction(m_actions->link);
    bar->addSeparator();
    bar->addActions({m_actions->heatMap, m_actions->wipe});
    bar->addSeparator();
    for (QAction* a : bake->actions()) {
        if (!a->isSeparator() && a->shortcut() == QKeySequence(Qt::CTRL | Qt::Key_B)) {
            a->setIcon(icon("bake"));
            bar->addAction(a);
        }
    }
    bar->addAction(run);
    m_panelsMenu->addAction(bar->toggleViewAction());
}

namespace {

QString shortcutRow(const QString& what, const QString& keys) {
    return QStringLiteral("<tr><td>%1</td><td><b>%2</b></td></tr>").arg(what, keys);
}

QString groupHeading(const QString& title) {
    return QStringLiteral("<tr><th colspan=2 align=left><br>%1</th></tr>").arg(title);
}

// Every action of `menu` and its submenus that has a shortcut, once.
void collectShortcuts(const QMenu* menu, QStringList& rows, QSet<const QAction*>& seen) {
    for (const QAction* a : menu->actions()) {
        if (a->menu()) {
            collectShortcuts(a->menu(), rows, seen);
        } else if (!a->shortcut().isEmpty() && !a->text().isEmpty() && !seen.contains(a)) {
            seen.insert(a);
            rows << shortcutRow(a->text().remove(QLatin1Char('&')),
                                a->shortcut().toString(QKeySequence::NativeText));
        }
    }
}

} // namespace

QString MainWindow::shortcutsTable() const {
    QString html;
    QSet<const QAction*> seen;
    for (const QAction* top : menuBar()->actions()) {
        if (!top->menu())
            continue;
        QStringList rows;
        collectShortcuts(top->menu(), rows, seen);
        if (!rows.isEmpty())
            html += groupHeading(top->text().remove(QLatin1Char('&'))) + rows.join(QString());
    }
    QStringList other;
    for (const QAction* a : findChildren<QAction*>()) {
        if (!a->shortcut().isEmpty() && !a->text().isEmpty() && !seen.contains(a)) {
            seen.insert(a);
            other << shortcutRow(a->text().remove(QLatin1Char('&')),
                                 a->shortcut().toString(QKeySequence::NativeText));
        }
    }
    other.sort();
    if (!other.isEmpty())
        html += groupHeading(tr("In a view")) + other.join(QString());
    html += groupHeading(tr("Mouse")) + shortcutRow(tr("Orbit"), tr("drag")) +
            shortcutRow(tr("Zoom"), tr("wheel")) +
            shortcutRow(tr("Move the light"), tr("Ctrl+drag")) +
            shortcutRow(tr("Move the A/B divider"), tr("drag the line"));
    return QStringLiteral("<table cellspacing=4>%1</table>").arg(html);
}

void MainWindow::showShortcuts() {
    // A dialog of its own (not a message box): its title is never cut, and the list scrolls.
    auto* dialog = new QDialog(this);
    dialog->setObjectName(QStringLiteral("shortcuts"));
    dialog->setWindowTitle(tr("Keyboard and Mouse Shortcuts"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* label = new QLabel(shortcutsTable(), dialog);
    label->setTextFormat(Qt::RichText);
    auto* scroll = new QScrollArea(dialog);
    scroll->setWidget(label);
    scroll->setWidgetResizable(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(scroll, 1);
    layout->addWidget(buttons);
    const int titleWidth = dialog->fontMetrics().horizontalAdvance(dialog->windowTitle());
    dialog->resize(std::max(label->sizeHint().width() + 48, titleWidth + 160),
                   std::min(label->sizeHint().height() + 80, 640));
    dialog->show();
}

} // namespace px::studio

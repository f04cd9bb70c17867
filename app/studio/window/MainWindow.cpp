#include "window/MainWindow.h"

#include "jobs/Baking.h"
#include "model/MaterialDocument.h"
#include "panels/ComparePanel.h"
#include "panels/MapsPanel.h"
#include "panels/MaterialPanel.h"
#include "panels/TechniquePanel.h"
#include "panels/ViewPanel.h"
#include "preview/GlSupport.h"
#include "preview/PreviewWidget.h"
#include "preview/SkyFollower.h"
#include "preview/Viewport.h"
#include "preview/ViewportGrid.h"
#include "widgets/WheelGuard.h"
#include "window/MainWindowActions.h"
#include "window/RecentFiles.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QKeyEvent>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QUndoView>
#include <QVBoxLayout>
#include <algorithm>
#include <chrono>
#include <memory>

// The icons live in the studio library's resources: a static library needs them registered.
static void initStudioResources() {
    Q_INIT_RESOURCE(studio);
}

namespace px::studio {

namespace {

QScrollArea* scrolled(QWidget* content) {
    auto* area = new QScrollArea;
    area->setWidget(content);
    area->setWidgetResizable(true);
    area->setFrameShape(QFrame::NoFrame);
    // On a small screen (1280 x 720, or 1920 x 1080 at scale 2) the panel may be narrower than
    // its content: it scrolls both ways rather than pushing the window past the screen.
    area->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    area->setMinimumWidth(std::min(content->sizeHint().width(), 220));
    return area;
}

} // namespace

MainWindow::MainWindow(const QString& liveReason, QWidget* parent)
    : QMainWindow(parent), m_document(new MaterialDocument(this)), m_baker(new BakeRunner(this)),
      m_recent(new RecentFiles(this)),
      m_recentMeshes(new RecentFiles(QStringLiteral("recentMeshes"), this)) {
    initStudioResources();
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    new WheelGuard(this); // before the panels: the wheel scrolls them, not their fields
    createPanels(liveReason);
    createActions();
    createMenus();
    qApp->installEventFilter(this); // Ctrl+Z in a spin box: see eventFilter

    m_rendererLabel = new QLabel(this);
    const GlProbe& gl = probeOpenGl();
    m_baker->setRenderer(gl.renderer);
    m_rendererLabel->setText(
        liveReason.isEmpty() ? tr("OpenGL %1.%2 · %3").arg(gl.major).arg(gl.minor).arg(gl.renderer)
                             : tr("No live preview"));
    m_rendererLabel->setToolTip(liveReason.isEmpty() ? tr("The renderer of the live preview.")
                                                     : liveReason);
    statusBar()->addPermanentWidget(m_rendererLabel);
    statusBar()->showMessage(tr("Drop maps, a folder or a material here. Drag in a view to "
                                "orbit, Ctrl+drag to move the light."),
                             8000);

    connect(m_document, &MaterialDocument::dirtyChanged, this, &MainWindow::updateTitle);
    connect(m_document, &MaterialDocument::changed, this, &MainWindow::updateTitle);
    connect(m_baker, &BakeRunner::finished, this, &MainWindow::onBakeFinished);
    connect(m_recent, &RecentFiles::changed, this, &MainWindow::updateRecentMenu);
    connect(m_recentMeshes, &RecentFiles::changed, this,
            [this] { m_viewPanel->setRecentMeshes(m_recentMeshes->files()); });
    m_viewPanel->setRecentMeshes(m_recentMeshes->files());
    connect(m_viewPanel, &ViewPanel::meshFileChosen, this,
            [this](const QString& path) { loadMesh(path); });
    connect(m_viewPanel, &ViewPanel::meshUvSetChosen, this,
            [this](int set) { loadMesh(m_viewports->activeView().meshFile, set); });
    connect(m_viewPanel, &ViewPanel::loadMeshRequested, this, &MainWindow::loadMeshDialog);
    connect(m_viewPanel, &ViewPanel::environmentChosen, this, &MainWindow::setEnvironment);
    connect(m_viewPanel, &ViewPanel::loadEnvironmentRequested, this,
            &MainWindow::loadEnvironmentDialog);
    connect(m_viewports, &ViewportGrid::viewEdited, this, &MainWindow::rememberMaterialMesh);
    connect(m_viewports, &ViewportGrid::viewEdited, this, &MainWindow::rememberMaterialLight);
    new SkyFollower(m_viewports, this); // the sky's sun moves with the light
    updateRecentMenu();
    updateTitle();
    resize(1400, 900);
    fitToScreen();
}

void MainWindow::fitToScreen() {
    // Never larger than the screen's free area (a restored or default size may be).
    const QScreen* screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
    if (!screen)
        return;
    const QSize free = screen->availableGeometry().size();
    const QSize frame = frameGeometry().size() - geometry().size(); // title bar and borders
    const QSize room = free - frame;
    if (width() > room.width() || height() > room.height())
        resize(size().boundedTo(room));
}

MainWindow::~MainWindow() = default;

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    // A spin box's line edit takes Ctrl+Z and Ctrl+Y for its own text, so undo did nothing while
    // one had focus. Here undo is the document's: the shortcut override is withheld from the
    // spin boxes of this window, and the Undo/Redo actions fire.
    if (event->type() == QEvent::ShortcutOverride) {
        const auto* key = static_cast<QKeyEvent*>(event);
        const QKeySequence pressed(key->keyCombination());
        auto* widget = qobject_cast<QWidget*>(watched);
        const bool undoKey = m_actions && (m_actions->undo->shortcuts().contains(pressed) ||
                                           m_actions->redo->shortcuts().contains(pressed));
        if (undoKey && widget && widget->window() == this &&
            (qobject_cast<QAbstractSpinBox*>(widget) ||
             qobject_cast<QAbstractSpinBox*>(widget->parentWidget())))
            return true;
    }
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::createPanels(const QString& liveReason) {
    m_viewports = new ViewportGrid(m_document, liveReason, this);
    setCentralWidget(m_viewports);
    // The side docks keep the window's full height: the Compare dock opens under the viewports,
    // not across the bottom of the Maps and Parameters panels.
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);

    auto* parameters = new QWidget;
    auto* parametersLayout = new QVBoxLayout(parameters);
    parametersLayout->setContentsMargins(4, 4, 4, 4);
    m_techniquePanel = new TechniquePanel(m_document, parameters);
    m_materialPanel = new MaterialPanel(m_document, parameters);
    m_viewPanel = new ViewPanel(m_viewports, parameters);
    parametersLayout->addWidget(m_techniquePanel);
    parametersLayout->addWidget(m_materialPanel);
    parametersLayout->addWidget(m_viewPanel);
    parametersLayout->addStretch();
    auto* parametersDock = new QDockWidget(tr("Parameters"), this);
    parametersDock->setObjectName(QStringLiteral("ParametersDock"));
    parametersDock->setWidget(scrolled(parameters));
    addDockWidget(Qt::RightDockWidgetArea, parametersDock);

    m_mapsPanel = new MapsPanel(m_document, m_baker);
    auto* mapsDock = new QDockWidget(tr("Maps"), this);
    mapsDock->setObjectName(QStringLiteral("MapsDock"));
    mapsDock->setWidget(scrolled(m_mapsPanel));
    addDockWidget(Qt::LeftDockWidgetArea, mapsDock);

    auto* history = new QUndoView(m_document->undoStack());
    history->setEmptyLabel(tr("<opened>"));
    auto* historyDock = new QDockWidget(tr("History"), this);
    historyDock->setObjectName(QStringLiteral("HistoryDock"));
    historyDock->setWidget(history);
    addDockWidget(Qt::LeftDockWidgetArea, historyDock);
    tabifyDockWidget(mapsDock, historyDock);
    mapsDock->raise();

    m_comparePanel = new ComparePanel(m_document, this);
    auto* compareDock = new QDockWidget(tr("Compare"), this);
    compareDock->setObjectName(QStringLiteral("CompareDock"));
    compareDock->setWidget(m_comparePanel);
    addDockWidget(Qt::BottomDockWidgetArea, compareDock);
    compareDock->hide();

    connect(m_viewports, &ViewportGrid::activeViewportChanged, m_techniquePanel,
            &TechniquePanel::setViewport);
    connect(m_comparePanel, &ComparePanel::settingChosen, this,
            [this](Technique technique, const TraceParams& params) {
                const int v = m_viewports->activeViewport();
                m_document->edit(tr("Viewport %1: %2 from Compare")
                                     .arg(v + 1)
                                     .arg(QString::fromUtf8(info(technique).name.data())),
                                 [=](DocumentState& s) {
                                     s.setView(v, {technique, params});
                                 });
                statusBar()->showMessage(
                    tr("Viewport %1 now traces with %2 (%3).")
                        .arg(v + 1)
                        .arg(QString::fromUtf8(info(technique).title.data()))
                        .arg(QString::fromStdString(settingLabel(technique, params))),
                    6000);
            });
    connect(m_materialPanel, &MaterialPanel::problem, this, [this](const QString& message) {
        showProblem(tr("Cannot read the height map"), message);
    });
    connect(m_materialPanel, &MaterialPanel::note, this,
            [this](const QString& message) { statusBar()->showMessage(message, 8000); });
    connect(m_materialPanel, &MaterialPanel::conesInvalidated, this,
            [this](bool cone, bool relaxed) {
                if (cone)
                    startBake(BakeKind::Cone);
                if (relaxed)
                    startBake(BakeKind::RelaxedCone);
            });
    connect(m_mapsPanel, &MapsPanel::loadRequested, this, &MainWindow::importMapDialog);
    connect(m_mapsPanel, &MapsPanel::fileDropped, this,
            [this](MapKind kind, const QString& path) { loadMap(kind, path); });
    connect(m_mapsPanel, &MapsPanel::bakeRequested, this, &MainWindow::startBake);
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("%1[*] — Parallax Studio").arg(m_document->displayName()));
    setWindowModified(m_document->isDirty());
}

void MainWindow::showProblem(const QString& title, const QString& message) {
    m_lastProblem = message;
    statusBar()->showMessage(message.section(QLatin1Char('\n'), 0, 0), 10000);
    emit problemShown(message);
    if (!m_interactive)
        return;
    // Window-modal and non-blocking: the event loop (and any running bake) goes on.
    auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::WindowModal);
    box->open();
}

void MainWindow::showNotes(const std::vector<std::string>& notes) {
    QStringList lines;
    for (const std::string& n : notes)
        lines << QString::fromStdString(n);
    if (!lines.isEmpty())
        statusBar()->showMessage(lines.join(QLatin1Char(' ')), 10000);
}

void MainWindow::startBake(BakeKind kind) {
    const DocumentState& state = m_document->state();
    if (!state.hasMap(MapKind::Height)) {
        showProblem(tr("Nothing to bake"), tr("Load a height map first."));
        return;
    }
    if (kind == BakeKind::Normal && state.hasMap(MapKind::Normal) && !state.normalBake) {
        // A loaded normal map is the artist's: replacing it with a bake is asked, not assumed.
        // Window-modal and non-blocking, like every message here.
        auto* box = new QMessageBox(
            QMessageBox::Question, tr("Replace the loaded normal map?"),
            tr("The normal map %1 was loaded from its file. Bake one from the height map in its "
               "place? (The file itself is not changed.)")
                .arg(QFileInfo(QString::fromStdString(state.material.maps.normal)).fileName()),
            QMessageBox::Cancel, this);
        box->setObjectName(QStringLiteral("confirm-normal-bake"));
        QPushButton* bake = box->addButton(tr("Bake"), QMessageBox::AcceptRole);
        box->setDefaultButton(QMessageBox::Cancel);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setWindowModality(Qt::WindowModal);
        connect(bake, &QPushButton::clicked, this, [this] { runBake(BakeKind::Normal); });
        box->open();
        return;
    }
    runBake(kind);
}

void MainWindow::runBake(BakeKind kind) {
    m_baker->start(makeBakeRequest(m_document->state(), kind, m_mapsPanel->normalFilter(),
                                   m_mapsPanel->occlusionDistance()));
    statusBar()->showMessage(
        tr("Baking the %1 in the background (Esc cancels)…").arg(bakeTitle(kind)));
}

void MainWindow::onBakeFinished(const BakeOutcome& outcome) {
    const QString what = bakeTitle(outcome.request.kind);
    if (outcome.cancelled) {
        statusBar()->showMessage(tr("The %1 bake was cancelled; nothing changed.").arg(what), 6000);
        return;
    }
    if (!outcome.error.isEmpty()) {
        showProblem(tr("Bake failed"), outcome.error);
        return;
    }
    Result<DocumentState> next = withBake(m_document->state(), outcome);
    if (!next) {
        showProblem(tr("Bake discarded"), QString::fromStdString(next.error().message));
        return;
    }
    m_document->edit(tr("Bake %1").arg(what), [&](DocumentState& s) { s = *next; });
    if (outcome.request.kind == BakeKind::BentNormal)
        saveBentNormals(outcome.bentNormals);
    // The wait the user sees runs from Bake to the views drawing the map, and can be much longer
    // than the bake: a baked normal map takes 0.05 s at 512², the views' new shader variant a
    // second on llvmpipe. Said once the active view has drawn it (with the new maps, not while
    // they still go up).
    const BakeKind kind = outcome.request.kind;
    const double bakeSeconds = outcome.seconds;
    const auto asked = outcome.request.asked;
    const QString where = bakeDevice(outcome);
    auto report = [this, kind, bakeSeconds, asked, where] {
        const double shown =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
        m_mapsPanel->showBakeShown(kind, bakeSeconds, where, shown);
        statusBar()->showMessage(
            tr("Baked the %1 in %2 s %3, shown %4 s after Bake; it is saved with the material.")
                .arg(bakeTitle(kind))
                .arg(bakeSeconds, 0, 'f', 2)
                .arg(where)
                .arg(shown, 0, 'f', 2),
            8000);
    };
    PreviewWidget* view = m_viewports->viewport(m_viewports->activeViewport())->preview();
    if (!view || !view->isVisible()) {
        report();
        return;
    }
    auto connection = std::make_shared<QMetaObject::Connection>();
    *connection = connect(view, &PreviewWidget::frameRendered, this, [view, connection, report] {
        if (view->uploading())
            return;
        disconnect(*connection);
        report();
    });
}

void MainWindow::restoreLayout() {
    const QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    const int count = settings.value(QStringLiteral("window/viewports"), 1).toInt();
    m_viewports->setLayoutCount(count);
    fitToScreen(); // the screen may be smaller than the one the layout was saved on
    m_layoutRestored = true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    if (m_layoutRestored) {
        QSettings settings;
        settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
        settings.setValue(QStringLiteral("window/state"), saveState());
        settings.setValue(QStringLiteral("window/viewports"), m_viewports->layoutCount());
    }
    m_baker->cancel();
    event->accept();
}

} // namespace px::studio

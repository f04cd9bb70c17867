#pragma once
// The editor's window: the viewport grid in the middle, the parameter, maps, compare and history
// panels around it, menus with shortcuts, status-bar hints, drag and drop, and the dirty prompt
// on close. The document does the editing; the window does files, dialogs and messages.
//
// One class in four files, all here, because one file would be over 900 lines: MainWindow.cpp
// builds the window and wires the panels, MainWindowFiles.cpp opens, saves and imports (menu,
// dialog, drop), MainWindowMenus.cpp makes the actions, menus and shortcuts, and
// MainWindowActions.h holds the actions more than one of them reach (private to the window).

#include "jobs/BakeRunner.h"
#include "jobs/MeshBakeJob.h"
#include "parallax/Result.h"
#include "parallax/material/MapKind.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QMainWindow>
#include <QPointer>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class QAction;
class QLabel;
class QMenu;

namespace px {
struct ImportedSet;
struct LoadedMesh;
} // namespace px

namespace px::studio {

class ComparePanel;
class ImportSummaryDialog;
class MapsPanel;
class MaterialDocument;
class MaterialPanel;
class RecentFiles;
class TechniquePanel;
class ViewPanel;
class ViewportGrid;
struct DocumentState;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // `liveReason` empty: live previews; otherwise why there are none (shown in each viewport).
    explicit MainWindow(const QString& liveReason, QWidget* parent = nullptr);
    ~MainWindow() override;

    MaterialDocument* document() const { return m_document; }
    ViewportGrid* viewports() const { return m_viewports; }
    MaterialPanel* materialPanel() const { return m_materialPanel; }
    TechniquePanel* techniquePanel() const { return m_techniquePanel; }
    ViewPanel* viewPanel() const { return m_viewPanel; }
    MapsPanel* mapsPanel() const { return m_mapsPanel; }
    ComparePanel* comparePanel() const { return m_comparePanel; }
    BakeRunner* baker() const { return m_baker; }
    RecentFiles* recentFiles() const { return m_recent; }

    // File operations as the menus, dialogs and drops use them. Each failure shows a message
    // naming the file and leaves the document as it was; they return whether they succeeded.
    void newSample(ProceduralMap kind, int size = 512);
    // A material with no maps (asks first where work would be lost): a height map to load next.
    void newEmptyMaterial();
    bool openFile(const QString& path);
    bool saveTo(const QString& path);
    bool loadMap(MapKind kind, const QString& path, bool depth = false);
    // A folder or files holding a texture set become a new material named after the set, never
    // merged into the open one; `set` chooses where there are several (empty: ask, or refuse when
    // not interactive). A set with only a normal map asks (the box "derive-height") whether to
    // make its height map, and is imported once answered. A single image adds to the material
    // being edited, as one undoable step.
    bool importFolder(const QString& folder, const QString& set = {});
    bool importFiles(const QStringList& paths, const QString& set = {}); // what a drop does
    // The preview's own mesh (MainWindowMesh.cpp): an OBJ or glTF file loaded in the background
    // with progress, drawn by the active viewport (every viewport while linked), added to the
    // recent meshes and remembered for the material in the editor's settings (not in the material
    // file: the mesh is how this editor previews it, not part of it). A failure shows a message
    // naming the file and keeps the mesh drawn before. `uvSet` < 0: the set this file was last
    // shown with (the first if it has no such set any more).
    static constexpr int kRememberedUvSet = -1;
    bool loadMesh(const QString& path, int uvSet = kRememberedUvSet);
    RecentFiles* recentMeshes() const { return m_recentMeshes; }
    // Image-based light in the active viewport (all while linked): "" none, "sky" the built-in one
    // (its sun where the light is, following it: SkyFollower.h), else an HDR/EXR file; made in the
    // background. A failure shows a message naming the file and keeps the environment drawn
    // before.
    bool setEnvironment(const QString& source);
    // Pictures out (MainWindowPictures.cpp), rendered offscreen at `size` pixels per view without
    // the overlays, written atomically as PNG: the active view, or every shown view side by side
    // as the grid places them; a turntable of the active view, the camera orbiting once in
    // `frames` steps, FILE-000.png ... written as one set, one frame per turn of the event loop
    // under a progress dialog with Cancel (a failure or a cancel keeps the previous set).
    bool saveViewImage(const QString& file, QSize size, bool allViews);
    bool saveTurntable(const QString& file, QSize size, int frames);
    // The mesh file remembered for a material file, or empty, and the uv set it was shown with.
    static QString rememberedMesh(const QString& materialPath);
    static int rememberedMeshUvSet(const QString& materialPath);
    // Tests: called on the loading thread with each progress report of a mesh load (a test holds
    // the load there to see the progress dialog).
    void setMeshProgressObserver(std::function<void(float)> observer) {
        m_meshProgressObserver = std::move(observer);
    }
    // The last import's summary (hidden when not interactive; tests read and click it).
    ImportSummaryDialog* importSummary() const;
    // Bakes in the background; over a normal map loaded from a file it asks first.
    void startBake(BakeKind kind);
    // Bake ▸ From Mesh… without its dialog (MainWindowMeshBake.cpp): reads the mesh unless given,
    // bakes in the background, adopts the result as a new material (one undo step).
    bool bakeFromMesh(const QString& path, const MeshBakeOptions& options,
                      SharedBakeMesh mesh = {});

    // The window's size, docks and layout as the user left them (settings), restored at start-up
    // of an interactive session (not for screenshots and tests, which want a known layout).
    void restoreLayout();

    // The shortcut list of Help > Keyboard Shortcuts (F1), grouped by menu, as HTML.
    QString shortcutsTable() const;

    // The last problem shown to the user (tests read it; the message box shows it).
    QString lastProblem() const { return m_lastProblem; }
    // False: problems go to lastProblem() and the status bar only (tests, --screenshot).
    void setInteractive(bool interactive) { m_interactive = interactive; }

signals:
    void problemShown(const QString& message);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createPanels(const QString& liveReason);
    void createActions();
    void createMenus();
    void updateTitle();
    void fitToScreen();
    void updateRecentMenu();
    void showProblem(const QString& title, const QString& message);
    void showNotes(const std::vector<std::string>& notes);
    void adopt(const QString& text, const DocumentState& state);
    bool importSet(const std::vector<std::string>& files, const QString& source, QString set);
    void showImportSummary(const ImportedSet& set);
    void offerDerivedHeight(ImportedSet set);
    void adoptImported(const ImportedSet& set);
    bool maybeSave(); // false: the user cancelled
    bool save();
    bool saveAs();
    void openDialog();
    void importMapDialog(MapKind kind);
    void importFolderDialog();
    void loadMeshDialog();
    void loadEnvironmentDialog();
    enum class PictureKind { ActiveView, AllViews, Turntable };
    void picturesDialog(PictureKind kind);
    Result<LoadedMesh> readMesh(const QString& path, int uvSet);
    bool loadMeshWith(const QString& path, int uvSet, bool remembered);
    void rememberMaterialMesh();
    void restoreMaterialMesh();
    void rememberMaterialLight(); // MainWindowEnvironment.cpp
    void restoreMaterialLight();
    void exportDialog();
    void showShortcuts();
    void runBake(BakeKind kind);
    void bakeFromMeshDialog();
    SharedBakeMesh readMeshForBake(const QString& path, MeshUp up);
    void onBakeFinished(const BakeOutcome& outcome);
    void saveBentNormals(const Image& bentNormals); // MainWindowBentNormals.cpp
    void bakeMissingConeMaps();

    MaterialDocument* m_document;
    BakeRunner* m_baker;
    RecentFiles* m_recent;
    RecentFiles* m_recentMeshes;
    ViewportGrid* m_viewports = nullptr;
    MaterialPanel* m_materialPanel = nullptr;
    TechniquePanel* m_techniquePanel = nullptr;
    ViewPanel* m_viewPanel = nullptr;
    MapsPanel* m_mapsPanel = nullptr;
    ComparePanel* m_comparePanel = nullptr;
    QLabel* m_rendererLabel = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_panelsMenu = nullptr;
    QPointer<ImportSummaryDialog> m_importSummary;
    QString m_lastProblem;
    bool m_interactive = true;
    std::function<void(float)> m_meshProgressObserver;
    bool m_layoutRestored = false;   // save it on close only if it was restored
    bool m_restoringPreview = false; // opening a material: what it is previewed with is not new

    struct Actions;
    std::unique_ptr<Actions> m_actions;
};

} // namespace px::studio

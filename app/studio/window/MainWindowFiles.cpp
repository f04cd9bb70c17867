// MainWindow: opening, saving and importing, by menu, dialog and drop.

#include "jobs/BackgroundLoad.h"
#include "model/MapLoading.h"
#include "model/MaterialDocument.h"
#include "model/MaterialSaver.h"
#include "model/SampleMaterial.h"
#include "panels/ExportDialog.h"
#include "panels/ImportSummaryDialog.h"
#include "panels/MaterialPanel.h"
#include "panels/SetPickerDialog.h"
#include "parallax/material/MapFileName.h"
#include "parallax/mesh/MeshLoader.h"
#include "preview/ViewportGrid.h"
#include "widgets/FileDialogs.h"
#include "window/MainWindow.h"
#include "window/RecentFiles.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QScopedValueRollback>
#include <QStatusBar>

namespace px::studio {

namespace {

// A cancelled load (BackgroundLoad.h) is no problem to report: nothing changed, and it says so.
bool cancelledLoad(QStatusBar* bar, const Error& error) {
    if (!error.cancelled())
        return false;
    bar->showMessage(QObject::tr("Loading cancelled; nothing changed."), 6000);
    return true;
}

} // namespace

namespace {

const QString kImageFilter =
    QObject::tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.exr *.bmp *.tga *.hdr);;All files (*)");
const QString kMaterialFilter = QObject::tr("Materials (*.json);;All files (*)");

// Where the open material is, for dialogs not used yet (FileDialogs.h); empty for a new one.
QString folderOf(const QString& file) {
    return file.isEmpty() ? QString() : QFileInfo(file).absolutePath();
}

bool isMaterialFile(const QString& path) {
    return QFileInfo(path).suffix().compare(QLatin1String("json"), Qt::CaseInsensitive) == 0;
}

} // namespace

void MainWindow::newSample(ProceduralMap kind, int size) {
    if (!maybeSave())
        return;
    m_document->reset(makeSampleState(kind, size), {});
    statusBar()->showMessage(
        tr("The built-in %1 sample: its maps are made here and saved with "
           "the material.")
            .arg(QString::fromUtf8(proceduralMapNames()[static_cast<std::size_t>(kind)].data())),
        8000);
}

void MainWindow::newEmptyMaterial() {
    if (!maybeSave())
        return;
    m_document->reset(DocumentState{}, {});
    statusBar()->showMessage(tr("A new empty material: load or drop its height map, or import a "
                                "texture set."),
                             8000);
}

bool MainWindow::openFile(const QString& path) {
    if (!maybeSave())
        return false;
    Result<Loaded> loaded =
        loadInBackground<Loaded>(this, QFileInfo(path).fileName(),
                                 [file = path.toStdString()] { return openMaterialFile(file); });
    if (!loaded) {
        if (cancelledLoad(statusBar(), loaded.error()))
            return false;
        showProblem(tr("Cannot open the material"), QString::fromStdString(loaded.error().message));
        return false;
    }
    m_document->reset(loaded->state, QFileInfo(path).absoluteFilePath());
    m_recent->add(path);
    showNotes(loaded->notes);
    bakeMissingConeMaps();
    {
        // Read back as a whole: loading the mesh must not record the light it finds.
        const QScopedValueRollback restoring(m_restoringPreview, true);
        restoreMaterialMesh();
        restoreMaterialLight();
        if (const std::optional<LightDirection> light = m_document->material().light) {
            SharedView view = m_viewports->activeView();
            view.light.azimuthDeg = light->azimuthDeg;
            view.light.elevationDeg = light->elevationDeg;
            m_viewports->editView(view);
        }
    }
    return true;
}

void MainWindow::bakeMissingConeMaps() {
    // A viewport on a cone technique without its map (a material saved without one, a new height
    // map): bake it in the background; the viewport says it is waiting meanwhile.
    const DocumentState& s = m_document->state();
    if (!s.hasMap(MapKind::Height) || m_baker->isBusy())
        return;
    bool cone = false, relaxed = false;
    for (int v = 0; v < m_viewports->layoutCount(); ++v) {
        const TechniqueInfo& t = info(s.view(v).technique);
        cone |= t.needsConeMap && !s.hasMap(MapKind::Cone);
        relaxed |= t.needsRelaxedConeMap && !s.hasMap(MapKind::RelaxedCone);
    }
    if (cone)
        startBake(BakeKind::Cone);
    if (relaxed)
        startBake(BakeKind::RelaxedCone);
}

bool MainWindow::saveTo(const QString& path) {
    // The light the material is seen under goes into its file (the view's, not an undo step).
    DocumentState state = m_document->state();
    const DirectionalLight& light = m_viewports->activeView().light;
    state.material.light = LightDirection{light.azimuthDeg, light.elevationDeg};
    Result<DocumentState> saved = saveDocumentState(state, path.toStdString());
    if (!saved) {
        showProblem(tr("Cannot save the material"), QString::fromStdString(saved.error().message));
        return false;
    }
    m_document->markSaved(*saved, QFileInfo(path).absoluteFilePath());
    m_recent->add(path);
    rememberMaterialMesh();
    rememberMaterialLight();
    statusBar()->showMessage(tr("Saved %1.").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MainWindow::save() {
    if (m_document->filePath().isEmpty())
        return saveAs();
    return saveTo(m_document->filePath());
}

bool MainWindow::saveAs() {
    QString suggestion = m_document->filePath();
    if (suggestion.isEmpty())
        suggestion = QString::fromStdString(m_document->material().name) + QStringLiteral(".json");
    const QString path =
        askSaveFile(this, FileKind::Material, tr("Save Material"), suggestion, kMaterialFilter);
    if (path.isEmpty())
        return false;
    return saveTo(path);
}

bool MainWindow::maybeSave() {
    if (!m_document->isDirty() || !m_interactive)
        return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"),
        tr("%1 has changes that are not saved. Save them?").arg(m_document->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::adopt(const QString& text, const DocumentState& state) {
    m_document->edit(text, [&](DocumentState& s) { s = state; });
    bakeMissingConeMaps();
}

bool MainWindow::loadMap(MapKind kind, const QString& path, bool depth) {
    if (kind == MapKind::Height && !depth) {
        const std::optional<SuffixMatch> match = mapKindFromFileName(path.toStdString());
        depth = match && match->depth;
    }
    Result<Loaded> loaded =
        loadInBackground<Loaded>(this, QFileInfo(path).fileName(),
                                 [state = m_document->state(), kind, file = path.toStdString(),
                                  depth] { return loadMapFile(state, kind, file, depth); });
    if (!loaded) {
        if (cancelledLoad(statusBar(), loaded.error()))
            return false;
        showProblem(
            tr("Cannot load the %1 map").arg(QString::fromUtf8(mapTitle(kind).data()).toLower()),
            QString::fromStdString(loaded.error().message));
        return false;
    }
    adopt(tr("Load %1 map").arg(QString::fromUtf8(mapTitle(kind).data()).toLower()), loaded->state);
    statusBar()->showMessage(tr("Loaded %1 as the %2 map.")
                                 .arg(QFileInfo(path).fileName())
                                 .arg(QString::fromUtf8(mapTitle(kind).data()).toLower()),
                             6000);
    showNotes(loaded->notes);
    return true;
}

bool MainWindow::importFolder(const QString& folder, const QString& set) {
    Result<std::vector<std::string>> files = folderFiles(folder.toStdString());
    if (!files) {
        showProblem(tr("Cannot import the folder"), QString::fromStdString(files.error().message));
        return false;
    }
    return importSet(*files, folder, set);
}

bool MainWindow::importFiles(const QStringList& paths, const QString& set) {
    if (paths.size() == 1 && isMaterialFile(paths.front()))
        return openFile(paths.front());
    if (paths.size() == 1 && QFileInfo(paths.front()).isDir())
        return importFolder(paths.front(), set);
    std::vector<std::string> files;
    for (const QString& p : paths)
        files.push_back(p.toStdString());
    // One image is one map of the material being edited (an undoable step), known by its
    // suffix; with no known suffix, the height map: that is what this editor is about.
    if (paths.size() == 1) {
        const std::optional<SuffixMatch> match = mapKindFromFileName(files.front());
        const NameReading name = readMapFileName(files.front()).front();
        if (!match && name.tag && !name.glued) {
            // Packed, gloss or unused maps are read with their set, never as a height map.
            const std::string_view what =
                name.tag->what.empty() ? roleName(name.tag->role) : name.tag->what;
            showProblem(
                tr("Not a map on its own"),
                tr("%1: %2 by its name; import its set's folder to use it.")
                    .arg(QFileInfo(paths.front()).fileName(),
                         QString::fromUtf8(what.data(), static_cast<qsizetype>(what.size()))));
            return false;
        }
        return loadMap(match ? match->kind : MapKind::Height, paths.front());
    }
    return importSet(files, paths.size() == 1 ? paths.front() : tr("the dropped files"), set);
}

bool MainWindow::importSet(const std::vector<std::string>& files, const QString& source,
                           QString set) {
    const std::vector<std::string> names = textureSetNames(files);
    if (set.isEmpty() && names.size() > 1 && m_interactive) {
        // Never mixed: the user says which, from a list to filter that marks the sets without
        // relief.
        SetPickerDialog picker(QFileInfo(source).fileName(), setChoices(files), this);
        if (picker.exec() != QDialog::Accepted || picker.chosen().isEmpty())
            return false;
        set = picker.chosen();
    }
    Result<TextureSetPlan> plan = planTextureSet(files, source.toStdString(), set.toStdString());
    if (!plan) {
        showProblem(tr("Nothing imported"), QString::fromStdString(plan.error().message));
        return false;
    }
    // Never merged into the open material: a set is a material of its own.
    if (!maybeSave())
        return false;
    Result<ImportedSet> imported = loadInBackground<ImportedSet>(
        this, QString::fromStdString(plan->name), [set = *plan] { return importTextureSet(set); });
    if (!imported) {
        if (cancelledLoad(statusBar(), imported.error()))
            return false;
        showProblem(tr("Cannot import the texture set"),
                    QString::fromStdString(imported.error().message));
        return false;
    }
    if (imported->heightMissing) {
        offerDerivedHeight(std::move(*imported));
        return false; // imported once the user says how (offerDerivedHeight)
    }
    adoptImported(*imported);
    return true;
}

void MainWindow::offerDerivedHeight(ImportedSet set) {
    // Only a normal map: parallax needs a height map, which can be integrated from it.
    auto* box = new QMessageBox(
        QMessageBox::Question, tr("No height map"),
        tr("The texture set %1 has no height map, only the normal map %2. Make a height map "
           "from the normal map (integrated from its slopes; marked as derived)?")
            .arg(QString::fromStdString(set.plan.name),
                 QFileInfo(QString::fromStdString(set.material.maps.normal)).fileName()),
        QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("derive-height"));
    QPushButton* make = box->addButton(tr("Make a Height Map"), QMessageBox::AcceptRole);
    box->setDefaultButton(make);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::WindowModal);
    auto held = std::make_shared<ImportedSet>(std::move(set));
    connect(make, &QPushButton::clicked, this, [this, held] {
        Result<ImportedSet> derived = loadInBackground<ImportedSet>(
            this, tr("height map"), [set = *held]() mutable -> Result<ImportedSet> {
                if (Status s = deriveHeight(set); !s)
                    return s.error();
                return std::move(set);
            });
        if (!derived) {
            if (!cancelledLoad(statusBar(), derived.error()))
                showProblem(tr("Cannot make the height map"),
                            QString::fromStdString(derived.error().message));
            return;
        }
        adoptImported(*derived);
    });
    box->open();
}

void MainWindow::adoptImported(const ImportedSet& set) {
    DocumentState state = importedState(set);
    state.views = m_document->state().views; // the viewports' techniques are not the material's
    // A height map derived from the normal map is work on no disk: unsaved until saved, so the
    // next import or open asks before replacing it.
    const bool derived = state.isUnsaved(MapKind::Height);
    m_document->reset(std::move(state), {}, derived);
    showImportSummary(set);
    bakeMissingConeMaps();
}

ImportSummaryDialog* MainWindow::importSummary() const {
    return m_importSummary;
}

void MainWindow::showImportSummary(const ImportedSet& set) {
    delete m_importSummary; // the previous import's, if still open
    m_importSummary = new ImportSummaryDialog(set, this);
    m_importSummary->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_importSummary, &ImportSummaryDialog::flipRequested, m_materialPanel,
            &MaterialPanel::flipDepth);
    statusBar()->showMessage(QString::fromStdString(set.relief.summary), 15000);
    if (m_interactive)
        m_importSummary->show();
}

void MainWindow::openDialog() {
    const QString path = askOpenFile(this, FileKind::Material, tr("Open Material"), kMaterialFilter,
                                     folderOf(m_document->filePath()));
    if (!path.isEmpty())
        openFile(path);
}

void MainWindow::importMapDialog(MapKind kind) {
    const QString path = askOpenFile(
        this, FileKind::Map, tr("Load %1 Map").arg(QString::fromUtf8(mapTitle(kind).data())),
        kImageFilter, folderOf(m_document->filePath()));
    if (!path.isEmpty())
        loadMap(kind, path);
}

void MainWindow::importFolderDialog() {
    const QString folder = askFolder(this, FileKind::TextureFolder, tr("Import a Folder of Maps"),
                                     folderOf(m_document->filePath()));
    if (!folder.isEmpty())
        importFolder(folder);
}

void MainWindow::exportDialog() {
    if (m_document->state().anyUnsaved() || m_document->filePath().isEmpty()) {
        const auto answer = QMessageBox::question(
            this, tr("Save first"),
            tr("Some maps were made here and have no file yet. Save the material first?"),
            QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Save);
        if (answer != QMessageBox::Save || !save())
            return;
    }
    ExportDialog dialog(m_document->material(), m_document->filePath(), this);
    dialog.exec();
}

void MainWindow::updateRecentMenu() {
    if (!m_recentMenu)
        return;
    m_recentMenu->clear();
    for (const QString& file : m_recent->files()) {
        QAction* a = m_recentMenu->addAction(QFileInfo(file).fileName());
        a->setStatusTip(file);
        connect(a, &QAction::triggered, this, [this, file] {
            if (!openFile(file) && !QFileInfo::exists(file))
                m_recent->remove(file);
        });
    }
    if (!m_recent->files().isEmpty()) {
        m_recentMenu->addSeparator();
        m_recentMenu->addAction(tr("Clear Recent Files"), m_recent, &RecentFiles::clear);
    }
    m_recentMenu->setEnabled(!m_recent->files().isEmpty());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    QStringList paths;
    for (const QUrl& url : event->mimeData()->urls()) {
        if (url.isLocalFile())
            paths << url.toLocalFile();
    }
    if (paths.isEmpty())
        return;
    event->acceptProposedAction();
    // A mesh file is shown, not imported; maps dropped with it are imported as ever.
    QStringList maps;
    for (const QString& p : paths) {
        if (isMeshFile(p.toStdString()))
            loadMesh(p);
        else
            maps << p;
    }
    if (!maps.isEmpty())
        importFiles(maps);
}

} // namespace px::studio

// MainWindow: the preview's own mesh — Load Mesh… (dialog), drops, recent meshes, and the mesh each
// material was last previewed on, kept in the editor's settings beside the recent files, each
// with the uv set it was last shown with.

#include "jobs/BackgroundLoad.h"
#include "model/MaterialDocument.h"
#include "panels/ViewPanel.h"
#include "parallax/mesh/MeshLoader.h"
#include "preview/ViewportGrid.h"
#include "widgets/FileDialogs.h"
#include "window/MainWindow.h"
#include "window/MaterialSettings.h"
#include "window/RecentFiles.h"

#include <QFileInfo>
#include <QSettings>
#include <QStatusBar>
#include <atomic>
#include <memory>

namespace px::studio {

namespace {

const QString kMeshFilter = QObject::tr("Meshes (*.obj *.gltf *.glb);;All files (*)");

QString meshKey(const QString& materialPath) {
    return settingsKeyForFile("previewMesh", materialPath);
}

QString materialUvSetKey(const QString& materialPath) {
    return settingsKeyForFile("previewMeshUvSet", materialPath);
}

// The uv set a mesh file was last shown with, whatever the material (the recent meshes).
QString meshUvSetKey(const QString& meshPath) {
    return settingsKeyForFile("meshUvSet", meshPath);
}

} // namespace

QString MainWindow::rememberedMesh(const QString& materialPath) {
    return QSettings().value(meshKey(materialPath)).toString();
}

int MainWindow::rememberedMeshUvSet(const QString& materialPath) {
    return QSettings().value(materialUvSetKey(materialPath), 0).toInt();
}

Result<LoadedMesh> MainWindow::readMesh(const QString& path, int uvSet) {
    // The worker reports progress through `progress` and stops at its next report once `stop` is
    // set (a cancelled load's result is dropped anyway: this only spares the work).
    auto progress = std::make_shared<std::atomic<float>>(0.0f);
    auto stop = std::make_shared<std::atomic<bool>>(false);
    Result<LoadedMesh> loaded = runInBackground<LoadedMesh>(
        this, tr("Loading %1…").arg(QFileInfo(path).fileName()),
        [file = path.toStdString(), uvSet, progress, stop, observer = m_meshProgressObserver] {
            MeshLoadOptions options;
            options.uvSet = uvSet;
            options.progress = [progress, stop, observer](float f) {
                progress->store(f);
                if (observer)
                    observer(f);
                return !stop->load();
            };
            return px::loadMesh(file, options);
        },
        progress.get());
    if (!loaded)
        stop->store(true);
    return loaded;
}

bool MainWindow::loadMesh(const QString& path, int uvSet) {
    if (uvSet >= 0)
        return loadMeshWith(path, uvSet, false);
    return loadMeshWith(path, QSettings().value(meshUvSetKey(path), 0).toInt(), true);
}

bool MainWindow::loadMeshWith(const QString& path, int uvSet, bool remembered) {
    Result<LoadedMesh> loaded = readMesh(path, uvSet);
    // A remembered set the file no longer has: the first (a file may change between sessions).
    if (!loaded && !loaded.error().cancelled() && remembered && uvSet > 0)
        loaded = readMesh(path, 0);
    if (!loaded) {
        m_viewPanel->refresh();
        if (loaded.error().cancelled()) {
            statusBar()->showMessage(tr("Loading cancelled; nothing changed."), 6000);
            return false;
        }
        showProblem(tr("Cannot load the mesh"), QString::fromStdString(loaded.error().message));
        return false;
    }
    SharedView view = m_viewports->activeView();
    view.meshData = std::make_shared<const MeshData>(std::move(loaded->mesh));
    view.meshFile = QFileInfo(path).absoluteFilePath();
    view.meshUvSet = loaded->uvSet;
    view.meshUvSets = loaded->uvSets;
    m_viewports->showMesh(view);
    m_recentMeshes->add(path);
    QSettings().setValue(meshUvSetKey(path), view.meshUvSet);
    QString message = QString::fromStdString(loaded->summary());
    for (const std::string& note : loaded->notes)
        message += QStringLiteral("; ") + QString::fromStdString(note);
    statusBar()->showMessage(message, 10000);
    return true;
}

void MainWindow::loadMeshDialog() {
    const QString path = askOpenFile(this, FileKind::Mesh, tr("Load Mesh"), kMeshFilter);
    if (!path.isEmpty())
        loadMesh(path);
}

// Called whenever a view changes: writes only when the material's mesh or uv set did.
void MainWindow::rememberMaterialMesh() {
    const QString material = m_document->filePath();
    if (material.isEmpty() || m_restoringPreview)
        return;
    const SharedView& view = m_viewports->activeView();
    const QString mesh = view.meshData ? view.meshFile : QString();
    const int uvSet = view.meshData ? view.meshUvSet : 0;
    if (mesh == rememberedMesh(material) && uvSet == rememberedMeshUvSet(material))
        return;
    QSettings settings;
    if (mesh.isEmpty()) {
        settings.remove(meshKey(material));
        settings.remove(materialUvSetKey(material));
    } else {
        settings.setValue(meshKey(material), mesh);
        settings.setValue(materialUvSetKey(material), uvSet);
    }
}

void MainWindow::restoreMaterialMesh() {
    const QString material = m_document->filePath();
    const QString mesh = material.isEmpty() ? QString() : rememberedMesh(material);
    if (mesh.isEmpty())
        return;
    const int uvSet = rememberedMeshUvSet(material);
    const SharedView& view = m_viewports->activeView();
    if (mesh != view.meshFile || !view.meshData || uvSet != view.meshUvSet)
        loadMeshWith(mesh, uvSet, true);
}

} // namespace px::studio

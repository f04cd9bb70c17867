// MainWindow: the preview's own mesh — Load Mesh… (dialog), drops, recent meshes, and the mesh each
// material was last previewed on, kept in the editor's settings beside the recent files.

#include "jobs/BackgroundLoad.h"
#include "model/MaterialDocument.h"
#include "panels/ViewPanel.h"
#include "parallax/mesh/MeshLoader.h"
#include "preview/ViewportGrid.h"
#include "window/MainWindow.h"
#include "window/RecentFiles.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QStatusBar>
#include <QUrl>
#include <atomic>
#include <memory>

namespace px::studio {

namespace {

const QString kMeshFilter = QObject::tr("Meshes (*.obj *.gltf *.glb);;All files (*)");

// One settings key per material file; its path, percent-encoded, cannot open a settings group.
QString meshKey(const QString& materialPath) {
    return QStringLiteral("previewMesh/") +
           QString::fromLatin1(QUrl::toPercentEncoding(QFileInfo(materialPath).absoluteFilePath()));
}

} // namespace

QString MainWindow::rememberedMesh(const QString& materialPath) {
    return QSettings().value(meshKey(materialPath)).toString();
}

bool MainWindow::loadMesh(const QString& path, int uvSet) {
    // The worker reports progress through `progress` and stops at its next report once `stop` is
    // set (a cancelled load's result is dropped anyway: this only spares the work).
    auto progress = std::make_shared<std::atomic<float>>(0.0f);
    auto stop = std::make_shared<std::atomic<bool>>(false);
    Result<LoadedMesh> loaded = runInBackground<LoadedMesh>(
        this, tr("Loading %1…").arg(QFileInfo(path).fileName()),
        [file = path.toStdString(), uvSet, progress, stop] {
            MeshLoadOptions options;
            options.uvSet = uvSet;
            options.progress = [progress, stop](float f) {
                progress->store(f);
                return !stop->load();
            };
            return px::loadMesh(file, options);
        },
        progress.get());
    if (!loaded) {
        stop->store(true);
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
    m_viewports->editView(view);
    m_recentMeshes->add(path);
    QString message = QString::fromStdString(loaded->summary());
    for (const std::string& note : loaded->notes)
        message += QStringLiteral("; ") + QString::fromStdString(note);
    statusBar()->showMessage(message, 10000);
    return true;
}

void MainWindow::loadMeshDialog() {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Load Mesh"), QString(), kMeshFilter);
    if (!path.isEmpty())
        loadMesh(path);
}

// Called whenever a view changes: writes only when the material's mesh did.
void MainWindow::rememberMaterialMesh() {
    const QString material = m_document->filePath();
    if (material.isEmpty())
        return;
    const SharedView& view = m_viewports->activeView();
    const QString mesh = view.meshData ? view.meshFile : QString();
    if (mesh == rememberedMesh(material))
        return;
    QSettings settings;
    if (mesh.isEmpty())
        settings.remove(meshKey(material));
    else
        settings.setValue(meshKey(material), mesh);
}

void MainWindow::restoreMaterialMesh() {
    const QString material = m_document->filePath();
    const QString mesh = material.isEmpty() ? QString() : rememberedMesh(material);
    if (!mesh.isEmpty() && mesh != m_viewports->activeView().meshFile)
        loadMesh(mesh);
}

} // namespace px::studio

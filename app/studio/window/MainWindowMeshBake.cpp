// Bake ▸ From Mesh…: the dialog, the mesh read and the bake on workers behind the busy dialog (its
// bar and Cancel), and the result adopted as one undoable step: a new material with the maps.

#include "jobs/BackgroundLoad.h"
#include "jobs/MeshBakeJob.h"
#include "model/MaterialDocument.h"
#include "panels/MeshBakeDialog.h"
#include "widgets/FileDialogs.h"
#include "window/MainWindow.h"

#include <QFileInfo>
#include <QStatusBar>

namespace px::studio {

namespace {

const QString kBakeMeshFilter =
    QObject::tr("Meshes (*.obj *.ply *.stl *.gltf *.glb *.fbx);;All files (*)");

} // namespace

SharedBakeMesh MainWindow::readMeshForBake(const QString& path, MeshUp up) {
    auto progress = std::make_shared<std::atomic<float>>(0.0f);
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    Result<SharedBakeMesh> mesh = runInBackground<SharedBakeMesh>(
        this, tr("Reading %1…").arg(QFileInfo(path).fileName()),
        [file = path.toStdString(), up, progress, cancel] {
            return readBakeMesh(file, up, progress.get(), cancel.get());
        },
        progress.get());
    if (!mesh) {
        cancel->store(true);
        if (!mesh.error().cancelled())
            showProblem(tr("Cannot read the mesh"), QString::fromStdString(mesh.error().message));
        return nullptr;
    }
    for (const std::string& note : (*mesh)->notes)
        statusBar()->showMessage(QString::fromStdString(note), 8000);
    return *mesh;
}

void MainWindow::bakeFromMeshDialog() {
    auto* dialog = new MeshBakeDialog(
        [this](const QString& path, MeshUp up) { return readMeshForBake(path, up); },
        [this] { return askOpenFile(this, FileKind::Mesh, tr("Bake from Mesh"), kBakeMeshFilter); },
        this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowModality(Qt::WindowModal);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        bakeFromMesh(dialog->meshPath(), dialog->options(), dialog->mesh());
    });
    dialog->open();
}

bool MainWindow::bakeFromMesh(const QString& path, const MeshBakeOptions& options,
                              SharedBakeMesh mesh) {
    if (!mesh)
        mesh = readMeshForBake(path, MeshUp::Z);
    if (!mesh)
        return false;
    if (Status s = checkMeshBake(*mesh, options); !s) {
        showProblem(tr("Cannot bake from the mesh"), QString::fromStdString(s.error().message));
        return false;
    }
    auto progress = std::make_shared<std::atomic<float>>(0.0f);
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    Result<MeshBakeResult> baked = runInBackground<MeshBakeResult>(
        this, tr("Baking from %1…").arg(QFileInfo(path).fileName()),
        [mesh, options, progress, cancel] {
            return bakeMeshMaps(mesh, options, progress.get(), cancel.get());
        },
        progress.get());
    if (!baked) {
        cancel->store(true); // the worker stops at its next slice
        if (baked.error().cancelled()) {
            statusBar()->showMessage(tr("The bake from the mesh was cancelled; nothing changed."),
                                     6000);
        } else {
            showProblem(tr("Bake from the mesh failed"),
                        QString::fromStdString(baked.error().message));
        }
        return false;
    }
    const QString report =
        tr("Baked %1: height scale %2; %3 of %4 samples missed the mesh, %5 with overhangs.")
            .arg(QFileInfo(path).fileName())
            .arg(baked->heightScale)
            .arg(baked->misses)
            .arg(baked->samples)
            .arg(baked->overhangs);
    adopt(tr("Bake from mesh %1").arg(QFileInfo(path).fileName()),
          meshBakeState(m_document->state(), path.toStdString(), options, std::move(*baked)));
    statusBar()->showMessage(report, 10000);
    return true;
}

} // namespace px::studio

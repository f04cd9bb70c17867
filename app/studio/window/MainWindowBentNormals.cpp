// Bake > Bent Normal Map: the material has no slot for bent normals (the preview does not read
// them), so the bake's bent normal map is saved to a file the user names; its occlusion map, from
// the same horizons, fills the material's as Bake > Ambient Occlusion does.

#include "model/MaterialDocument.h"
#include "parallax/image/ImageFile.h"
#include "widgets/FileDialogs.h"
#include "window/MainWindow.h"

#include <QFileInfo>
#include <QStatusBar>

namespace px::studio {

void MainWindow::saveBentNormals(const Image& bentNormals) {
    const QString stem = QString::fromStdString(m_document->material().name);
    const QString file =
        askSaveFile(this, FileKind::Map, tr("Save Bent Normal Map"),
                    stem + QStringLiteral("_bent_normal.png"), tr("PNG images (*.png)"));
    if (file.isEmpty()) {
        statusBar()->showMessage(tr("The bent normal map was not saved (the occlusion map from "
                                    "the same bake is in the material)."),
                                 8000);
        return;
    }
    ImageWriteOptions options;
    options.format = PixelFormat::UInt16; // directions: 8 bits band on smooth relief
    if (Status s = writeImage(file.toStdString(), bentNormals, options); !s) {
        showProblem(tr("Bent normal map not saved"), QString::fromStdString(s.error().message));
        return;
    }
    statusBar()->showMessage(
        tr("Saved the bent normal map as %1 (16-bit, green as the material's normal maps).")
            .arg(QFileInfo(file).fileName()),
        8000);
}

} // namespace px::studio

// MainWindow: the preview's environment light — none, the built-in sky or an HDR/EXR file,
// prefiltered in the background (docs/lighting.md).

#include "jobs/BackgroundLoad.h"
#include "panels/ViewPanel.h"
#include "parallax/light/Environment.h"
#include "preview/ViewportGrid.h"
#include "widgets/FileDialogs.h"
#include "window/MainWindow.h"

#include <QFileInfo>
#include <QStatusBar>
#include <memory>

namespace px::studio {

namespace {
const QString kEnvironmentFilter =
    QObject::tr("Environments (*.hdr *.exr *.tif *.tiff *.png);;All files (*)");
}

bool MainWindow::setEnvironment(const QString& source) {
    SharedView view = m_viewports->activeView();
    if (source.isEmpty()) {
        view.environment.reset();
        view.environmentName.clear();
        m_viewports->editView(view);
        return true;
    }
    const bool sky = source == QLatin1String("sky");
    const glm::vec3 sun = view.light.direction();
    Result<PrefilteredEnvironment> made = runInBackground<PrefilteredEnvironment>(
        this, sky ? tr("Making the sky…") : tr("Loading %1…").arg(QFileInfo(source).fileName()),
        [sky, sun, file = source.toStdString()]() -> Result<PrefilteredEnvironment> {
            Result<Image> map =
                sky ? Result<Image>(makeSkyEnvironment(sun)) : loadEnvironment(file);
            if (!map)
                return map.error();
            return prefilterEnvironment(*map);
        });
    if (!made) {
        m_viewPanel->refresh();
        if (made.error().cancelled()) {
            statusBar()->showMessage(tr("Loading cancelled; nothing changed."), 6000);
            return false;
        }
        showProblem(tr("Cannot use the environment"), QString::fromStdString(made.error().message));
        return false;
    }
    view.environment = std::make_shared<const PrefilteredEnvironment>(std::move(*made));
    view.environmentName = sky ? source : QFileInfo(source).absoluteFilePath();
    view.skySun = sky ? sun : glm::vec3(0.0f);
    m_viewports->editView(view);
    return true;
}

void MainWindow::loadEnvironmentDialog() {
    const QString path =
        askOpenFile(this, FileKind::Environment, tr("Load Environment"), kEnvironmentFilter);
    if (!path.isEmpty())
        setEnvironment(path);
}

} // namespace px::studio

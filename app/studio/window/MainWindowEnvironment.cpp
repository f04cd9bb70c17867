// MainWindow: the preview's environment light — none, the built-in sky or an HDR/EXR file,
// prefiltered in the background (docs/lighting.md).

#include "jobs/BackgroundLoad.h"
#include "model/MaterialDocument.h"
#include "panels/ViewPanel.h"
#include "parallax/light/Environment.h"
#include "preview/ViewportGrid.h"
#include "widgets/FileDialogs.h"
#include "window/MainWindow.h"
#include "window/MaterialSettings.h"

#include <QFileInfo>
#include <QSettings>
#include <QStatusBar>
#include <memory>

namespace px::studio {

namespace {

const QString kEnvironmentFilter =
    QObject::tr("Environments, or one face of a sky box (*.hdr *.exr *.tif *.tiff *.png *.jpg "
                "*.jpeg *.tga *.bmp);;All files (*)");

// How a material file was last lit in the editor (its settings, as its mesh: MainWindowMesh.cpp):
// "previewEnvironment" is "sky", a file, or "" for none; a material never shown has no key.
struct LightKeys {
    QString environment, exposure, showEnvironment;
    explicit LightKeys(const QString& material)
        : environment(settingsKeyForFile("previewEnvironment", material)),
          exposure(settingsKeyForFile("previewExposure", material)),
          showEnvironment(settingsKeyForFile("previewShowEnvironment", material)) {}
};

QString environmentOf(const SharedView& view) {
    return view.environment ? view.environmentName : QString();
}

} // namespace

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

// Called whenever a view changes: writes only what changed.
void MainWindow::rememberMaterialLight() {
    const QString material = m_document->filePath();
    if (material.isEmpty() || m_restoringPreview)
        return;
    const SharedView& view = m_viewports->activeView();
    const LightKeys keys(material);
    QSettings settings;
    auto put = [&settings](const QString& key, const QVariant& value) {
        if (settings.value(key) != value)
            settings.setValue(key, value);
    };
    put(keys.environment, environmentOf(view));
    put(keys.exposure, double(view.exposure));
    put(keys.showEnvironment, view.showEnvironment);
}

void MainWindow::restoreMaterialLight() {
    const QString material = m_document->filePath();
    const LightKeys keys(material);
    const QSettings settings;
    if (material.isEmpty() || !settings.contains(keys.environment))
        return; // never shown here: the light stays as it is
    const QString environment = settings.value(keys.environment).toString();
    const float exposure = settings.value(keys.exposure, 0.0).toFloat();
    const bool show = settings.value(keys.showEnvironment, true).toBool();
    // The environment first (a file that is gone: a message, and the light drawn before stays).
    if (environment != environmentOf(m_viewports->activeView()))
        setEnvironment(environment);
    SharedView view = m_viewports->activeView();
    if (view.exposure != exposure || view.showEnvironment != show) {
        view.exposure = exposure;
        view.showEnvironment = show;
        m_viewports->editView(view);
    }
}

} // namespace px::studio

#include "panels/ViewPanel.h"

#include "preview/ViewInteraction.h"
#include "preview/ViewportGrid.h"
#include "widgets/Hints.h"
#include "widgets/SliderField.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>

namespace px::studio {

ViewPanel::ViewPanel(ViewportGrid* grid, QWidget* parent) : QWidget(parent), m_grid(grid) {
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* box = new QGroupBox(tr("Light and view"), this);
    outer->addWidget(box);
    auto* layout = new QVBoxLayout(box);

    m_azimuth = new SliderField(tr("Light azimuth"), {-180, 180, -180, 180, 0, 5}, this);
    m_elevation = new SliderField(tr("Light elevation"), {1, 90, 1, 90, 0, 5}, this);
    m_azimuth->setSuffix(QStringLiteral("°"));
    m_elevation->setSuffix(QStringLiteral("°"));
    m_azimuth->setHint(hints::lightAzimuth());
    m_elevation->setHint(hints::lightElevation());
    m_viewAngle = new SliderField(tr("View angle"),
                                  {90.0 - kMaxElevation, 90.0 - kMinElevation, 90.0 - kMaxElevation,
                                   90.0 - kMinElevation, 1, 1.0},
                                  this);
    m_viewAngle->setSuffix(QStringLiteral("°"));
    m_viewAngle->setHint(tr("The camera's angle from the surface normal (0° looks straight down, "
                            "89° grazes the surface): type an angle to compare views at it."));
    m_mesh = new QComboBox(this);
    for (std::string_view name : meshKindNames())
        m_mesh->addItem(QString::fromUtf8(name.data(), static_cast<int>(name.size())),
                        static_cast<int>(parseMeshKind(name).value_or(MeshKind::Plane)));
    m_builtIns = m_mesh->count();
    m_mesh->setToolTip(hints::mesh());
    m_mesh->setStatusTip(hints::mesh());
    m_loadMesh = new QPushButton(tr("Load…"), this);
    m_loadMesh->setToolTip(hints::loadMesh());
    m_loadMesh->setStatusTip(hints::loadMesh());
    m_uvSet = new QSpinBox(this);
    m_uvSet->setPrefix(tr("uv "));
    m_uvSet->setToolTip(tr("The mesh file's uv set the material uses (files with several)."));
    m_environment = new QComboBox(this);
    m_environment->addItem(tr("none (light and ambient)"), QString());
    m_environment->addItem(tr("sky (built in)"), QStringLiteral("sky"));
    m_environment->addItem(tr("Load HDR/EXR…"), QStringLiteral("load"));
    m_environment->setToolTip(hints::environment());
    m_environment->setStatusTip(hints::environment());
    m_exposure = new SliderField(tr("Exposure"), {-4, 4, -10, 10, 1, 0.1}, this);
    m_exposure->setSuffix(tr(" EV"));
    m_exposure->setHint(tr("Exposure in stops under the environment, before the filmic tone map."));
    m_showEnvironment = new QCheckBox(tr("Show the environment behind"), this);
    m_link = new QCheckBox(tr("Link viewports (camera and light)"), this);
    m_link->setToolTip(hints::linkViews());
    m_link->setStatusTip(hints::linkViews());
    auto* reset = new QPushButton(tr("Reset Camera"), this);
    reset->setToolTip(tr("Back to the default orbit (Home)."));

    auto* form = new QFormLayout;
    auto* meshRow = new QHBoxLayout;
    meshRow->addWidget(m_mesh, 1);
    meshRow->addWidget(m_uvSet);
    meshRow->addWidget(m_loadMesh);
    form->addRow(tr("Mesh"), meshRow);
    form->addRow(tr("Environment"), m_environment);
    layout->addWidget(m_azimuth);
    layout->addWidget(m_elevation);
    layout->addWidget(m_viewAngle);
    layout->addLayout(form);
    layout->addWidget(m_exposure);
    layout->addWidget(m_showEnvironment);
    layout->addWidget(m_link);
    layout->addWidget(reset);

    connect(m_azimuth, &SliderField::valueEdited, this, [this](double v) {
        SharedView view = m_grid->activeView();
        view.light.azimuthDeg = static_cast<float>(v);
        m_grid->editView(view);
    });
    connect(m_elevation, &SliderField::valueEdited, this, [this](double v) {
        SharedView view = m_grid->activeView();
        view.light.elevationDeg = static_cast<float>(v);
        m_grid->editView(view);
    });
    connect(m_viewAngle, &SliderField::valueEdited, this, [this](double v) {
        SharedView view = m_grid->activeView();
        view.camera = withPolarAngle(view.camera, v);
        m_grid->editView(view);
    });
    connect(m_mesh, &QComboBox::currentIndexChanged, this, &ViewPanel::chooseMesh);
    connect(m_loadMesh, &QPushButton::clicked, this, &ViewPanel::loadMeshRequested);
    connect(m_uvSet, &QSpinBox::valueChanged, this, [this](int set) {
        if (set != m_grid->activeView().meshUvSet)
            emit meshUvSetChosen(set);
        refresh();
    });
    connect(m_environment, &QComboBox::currentIndexChanged, this, [this](int i) {
        const QString source = m_environment->itemData(i).toString();
        if (source == QLatin1String("load"))
            emit loadEnvironmentRequested();
        else if (source != m_grid->activeView().environmentName)
            emit environmentChosen(source);
        refresh(); // what is drawn: the new environment once made, the old one if it failed
    });
    connect(m_exposure, &SliderField::valueEdited, this, [this](double v) {
        SharedView view = m_grid->activeView();
        view.exposure = static_cast<float>(v);
        m_grid->editView(view);
    });
    connect(m_showEnvironment, &QCheckBox::toggled, this, [this](bool on) {
        SharedView view = m_grid->activeView();
        view.showEnvironment = on;
        m_grid->editView(view);
    });
    connect(m_link, &QCheckBox::toggled, m_grid, &ViewportGrid::setLinked);
    connect(reset, &QPushButton::clicked, m_grid, &ViewportGrid::resetCameras);
    connect(m_grid, &ViewportGrid::viewEdited, this, &ViewPanel::refresh);
    connect(m_grid, &ViewportGrid::activeViewportChanged, this, &ViewPanel::refresh);
    connect(m_grid, &ViewportGrid::linkedChanged, this, &ViewPanel::refresh);
    refresh();
}

void ViewPanel::refresh() {
    const SharedView& view = m_grid->activeView();
    m_azimuth->setValue(view.light.azimuthDeg);
    m_elevation->setValue(view.light.elevationDeg);
    m_viewAngle->setValue(90.0 - view.camera.elevationDeg);
    const QSignalBlocker a(m_mesh), b(m_link);
    if (view.meshData) {
        if (m_mesh->findData(view.meshFile) < 0)
            m_mesh->addItem(QFileInfo(view.meshFile).fileName(), view.meshFile);
        m_mesh->setCurrentIndex(m_mesh->findData(view.meshFile));
    } else {
        m_mesh->setCurrentIndex(m_mesh->findData(static_cast<int>(view.mesh)));
    }
    m_link->setChecked(m_grid->linked());
    const QSignalBlocker c(m_environment), d(m_showEnvironment), e(m_uvSet);
    m_uvSet->setRange(0, view.meshData ? std::max(0, view.meshUvSets - 1) : 0);
    m_uvSet->setValue(view.meshData ? view.meshUvSet : 0);
    m_uvSet->setEnabled(view.meshData && view.meshUvSets > 1);
    int environment = m_environment->findData(view.environmentName);
    if (environment < 0) { // a file: listed before Load…
        m_environment->insertItem(m_environment->count() - 1,
                                  QFileInfo(view.environmentName).fileName(), view.environmentName);
        environment = m_environment->findData(view.environmentName);
    }
    m_environment->setCurrentIndex(environment);
    m_exposure->setValue(view.exposure);
    m_showEnvironment->setChecked(view.showEnvironment);
    m_exposure->setEnabled(static_cast<bool>(view.environment));
    m_showEnvironment->setEnabled(static_cast<bool>(view.environment));
}

void ViewPanel::setRecentMeshes(const QStringList& files) {
    {
        const QSignalBlocker block(m_mesh);
        while (m_mesh->count() > m_builtIns)
            m_mesh->removeItem(m_builtIns);
        for (const QString& file : files) {
            m_mesh->addItem(QFileInfo(file).fileName(), file);
            m_mesh->setItemData(m_mesh->count() - 1, file, Qt::ToolTipRole);
        }
    }
    refresh();
}

void ViewPanel::chooseMesh(int index) {
    if (index >= m_builtIns) {
        const QString file = m_mesh->itemData(index).toString();
        if (file != m_grid->activeView().meshFile || !m_grid->activeView().meshData)
            emit meshFileChosen(file);
        refresh(); // shows what is drawn: the new mesh once loaded, the old one if it failed
        return;
    }
    SharedView view = m_grid->activeView();
    view.mesh = static_cast<MeshKind>(m_mesh->itemData(index).toInt());
    view.meshData.reset();
    view.meshFile.clear();
    m_grid->showMesh(view);
}

} // namespace px::studio

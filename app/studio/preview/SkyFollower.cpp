#include "preview/SkyFollower.h"

#include "parallax/light/Environment.h"
#include "preview/ViewportGrid.h"

#include <QtConcurrent/QtConcurrentRun>

namespace px::studio {

SkyFollower::SkyFollower(ViewportGrid* grid, QObject* parent) : QObject(parent), m_grid(grid) {
    connect(m_grid, &ViewportGrid::viewEdited, this, &SkyFollower::follow);
    connect(m_grid, &ViewportGrid::activeViewportChanged, this, &SkyFollower::follow);
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &SkyFollower::made);
}

void SkyFollower::follow() {
    if (m_watcher.isRunning())
        return; // made() looks again
    const SharedView& view = m_grid->activeView();
    const glm::vec3 sun = view.light.direction();
    if (view.environmentName != QLatin1String("sky") || !view.environment || sun == view.skySun)
        return;
    m_sun = sun;
    m_replacing = view.environment;
    m_watcher.setFuture(
        QtConcurrent::run([sun] { return prefilterEnvironment(makeSkyEnvironment(sun)); }));
}

void SkyFollower::made() {
    SharedView view = m_grid->activeView();
    const std::shared_ptr<const PrefilteredEnvironment> replacing = std::move(m_replacing);
    if (view.environment == replacing && view.environmentName == QLatin1String("sky")) {
        view.environment = std::make_shared<const PrefilteredEnvironment>(m_watcher.result());
        view.skySun = m_sun;
        m_grid->editView(view); // viewEdited: follow() again if the light moved on meanwhile
        return;
    }
    follow();
}

} // namespace px::studio

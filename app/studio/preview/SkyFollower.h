#pragma once
// The built-in sky's sun is the directional light (docs/lighting.md): when the active view's light
// moves under the sky, the sky is made again with its sun there, on a worker (making and
// prefiltering it takes a few tenths of a second). A drag moves the light many times a second:
// one sky is made at a time, and when it is done the light as it is then gets the next.

#include "parallax/light/EnvironmentLighting.h"

#include <QFutureWatcher>
#include <QObject>
#include <glm/vec3.hpp>
#include <memory>

namespace px::studio {

class ViewportGrid;

class SkyFollower : public QObject {
    Q_OBJECT
public:
    explicit SkyFollower(ViewportGrid* grid, QObject* parent = nullptr);

private:
    void follow(); // a view changed, or a sky was just made
    void made();

    ViewportGrid* m_grid;
    QFutureWatcher<PrefilteredEnvironment> m_watcher;
    glm::vec3 m_sun{0.0f}; // of the sky being made
    // The sky it replaces: one chosen meanwhile (another file, the sky made anew) is kept.
    std::shared_ptr<const PrefilteredEnvironment> m_replacing;
};

} // namespace px::studio

#include "preview/ViewportGrid.h"

#include "preview/PreviewWidget.h"
#include "preview/Viewport.h"

#include <QGridLayout>
#include <algorithm>

namespace px::studio {

ViewportGrid::ViewportGrid(MaterialDocument* document, const QString& liveReason, QWidget* parent)
    : QWidget(parent) {
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setSpacing(4);
    for (int i = 0; i < 4; ++i) {
        auto* v = new Viewport(i, document, liveReason, this);
        m_viewports[static_cast<std::size_t>(i)] = v;
        connect(v, &Viewport::activated, this, &ViewportGrid::setActiveViewport);
        connect(v, &Viewport::cameraEdited, this, [this](int index, const OrbitCamera& c) {
            SharedView view = viewport(index)->view();
            view.camera = c;
            applyView(index, view);
        });
        connect(v, &Viewport::lightEdited, this, [this](int index, const DirectionalLight& l) {
            SharedView view = viewport(index)->view();
            view.light = l;
            applyView(index, view);
        });
    }
    relayout();
    setActiveViewport(0);
}

void ViewportGrid::setLayoutCount(int count) {
    count = count >= 4 ? 4 : (count >= 2 ? 2 : 1);
    if (count == m_count)
        return;
    m_count = count;
    relayout();
    if (m_active >= m_count)
        setActiveViewport(0);
    emit layoutCountChanged(m_count);
}

void ViewportGrid::relayout() {
    for (Viewport* v : m_viewports)
        m_grid->removeWidget(v);
    for (int i = 0; i < 4; ++i) {
        Viewport* v = m_viewports[static_cast<std::size_t>(i)];
        const bool shown = i < m_count;
        if (shown)
            m_grid->addWidget(v, m_count == 4 ? i / 2 : 0, m_count == 4 ? i % 2 : i);
        v->setVisible(shown);
    }
}

void ViewportGrid::setActiveViewport(int index) {
    index = std::clamp(index, 0, m_count - 1);
    const bool changed = index != m_active;
    m_active = index;
    for (Viewport* v : m_viewports)
        v->setActive(v->index() == m_active && m_count > 1);
    if (changed)
        emit activeViewportChanged(m_active);
}

void ViewportGrid::setLinked(bool linked) {
    if (linked == m_linked)
        return;
    m_linked = linked;
    if (m_linked) // everyone takes the active view's camera and light
        applyView(m_active, activeView());
    emit linkedChanged(m_linked);
}

const SharedView& ViewportGrid::activeView() const {
    return viewport(m_active)->view();
}

void ViewportGrid::editView(const SharedView& view) {
    applyView(m_active, view);
}

void ViewportGrid::showMesh(SharedView view) {
    const SharedView& shown = activeView();
    const bool sameMesh = view.meshData ? view.meshFile == shown.meshFile && shown.meshData
                                        : !shown.meshData && view.mesh == shown.mesh;
    if (!sameMesh)
        view.camera = framed(view.camera, view, aspect(m_active));
    applyView(m_active, view);
}

void ViewportGrid::resetCameras() {
    for (Viewport* v : m_viewports) {
        if (m_linked || v->index() == m_active) {
            SharedView view = v->view();
            view.camera = framed(defaultCamera(), view, aspect(m_active));
            v->setView(view);
        }
    }
    emit viewEdited();
}

float ViewportGrid::aspect(int index) const {
    const Viewport* v = viewport(index);
    const QWidget* picture = v->preview() ? static_cast<const QWidget*>(v->preview()) : v;
    return picture->height() > 0 ? float(picture->width()) / float(picture->height()) : 1.0f;
}

void ViewportGrid::applyView(int index, const SharedView& view) {
    for (Viewport* v : m_viewports) {
        if (m_linked || v->index() == index)
            v->setView(view);
    }
    emit viewEdited();
}

} // namespace px::studio

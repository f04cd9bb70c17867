#pragma once
// One, two or four viewports side by side, each with its own technique and quality, sharing the
// camera, light and mesh while linked (the default; unlink to move one alone). One viewport is
// active: the technique panel edits it and the compare panel applies to it.

#include "preview/ViewSettings.h"

#include <QWidget>
#include <array>

class QGridLayout;

namespace px::studio {

class MaterialDocument;
class Viewport;

class ViewportGrid : public QWidget {
    Q_OBJECT
public:
    ViewportGrid(MaterialDocument* document, const QString& liveReason, QWidget* parent = nullptr);

    int layoutCount() const { return m_count; }
    void setLayoutCount(int count); // 1, 2 or 4

    int activeViewport() const { return m_active; }
    void setActiveViewport(int index);

    bool linked() const { return m_linked; }
    void setLinked(bool linked);

    Viewport* viewport(int index) const { return m_viewports[static_cast<std::size_t>(index)]; }
    // The active viewport's camera, light and mesh (what the light panel shows).
    const SharedView& activeView() const;
    // Sets the light, mesh or camera of the active viewport, and of all while linked.
    void editView(const SharedView& view);
    // editView with another mesh: the camera, from the same angles, frames it whole (ViewSettings.h
    // framed()) when it is not the mesh shown before.
    void showMesh(SharedView view);
    // Every camera (the active one when unlinked) back to the default angles, framing its mesh.
    void resetCameras();
    // Width / height of viewport `index`'s picture.
    float aspect(int index) const;

signals:
    void activeViewportChanged(int index);
    void layoutCountChanged(int count);
    void linkedChanged(bool linked);
    void viewEdited(); // camera, light or mesh moved

private:
    void applyView(int index, const SharedView& view);
    void relayout();

    std::array<Viewport*, 4> m_viewports{};
    QGridLayout* m_grid;
    int m_count = 1;
    int m_active = 0;
    bool m_linked = true;
};

} // namespace px::studio

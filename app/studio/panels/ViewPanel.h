#pragma once
// Light and view: the directional light (also draggable in a view with Ctrl), the mesh, and
// whether the viewports share camera and light. View settings: not saved with the material.

#include <QWidget>

class QCheckBox;
class QComboBox;

namespace px::studio {

class SliderField;
class ViewportGrid;

class ViewPanel : public QWidget {
    Q_OBJECT
public:
    explicit ViewPanel(ViewportGrid* grid, QWidget* parent = nullptr);

    SliderField* lightAzimuth() const { return m_azimuth; }
    SliderField* lightElevation() const { return m_elevation; }
    SliderField* viewAngle() const { return m_viewAngle; } // the camera's polar angle
    QComboBox* mesh() const { return m_mesh; }
    QCheckBox* link() const { return m_link; }

private:
    void refresh();

    ViewportGrid* m_grid;
    SliderField* m_azimuth;
    SliderField* m_elevation;
    SliderField* m_viewAngle;
    QComboBox* m_mesh;
    QCheckBox* m_link;
};

} // namespace px::studio

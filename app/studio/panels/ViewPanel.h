#pragma once
// Light and view: the directional light (also draggable in a view with Ctrl), the mesh (a built-in
// one, a recent mesh file or Load Mesh…), and whether the viewports share camera and light. View
// settings: not saved with the material (a material's mesh is remembered in the editor's settings,
// MainWindowMesh.cpp).

#include <QWidget>

class QCheckBox;
class QComboBox;
class QPushButton;
class QSpinBox;

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
    QPushButton* loadMeshButton() const { return m_loadMesh; }
    QSpinBox* uvSet() const { return m_uvSet; }
    QCheckBox* link() const { return m_link; }
    QComboBox* environment() const { return m_environment; }
    SliderField* exposure() const { return m_exposure; }
    QCheckBox* showEnvironment() const { return m_showEnvironment; }

    // The recent mesh files, newest first, listed after the built-in meshes.
    void setRecentMeshes(const QStringList& files);

signals:
    void meshFileChosen(const QString& path); // a recent mesh picked: the window loads it
    void loadMeshRequested();                 // Load Mesh…
    void meshUvSetChosen(int set);            // read the mesh file again with this uv set
    // "" (none), "sky" or Load… picked in the environment list: the window makes it.
    void environmentChosen(const QString& source);
    void loadEnvironmentRequested();

public slots:
    void refresh();

private:
    void chooseMesh(int index);

    ViewportGrid* m_grid;
    SliderField* m_azimuth;
    SliderField* m_elevation;
    SliderField* m_viewAngle;
    QComboBox* m_mesh;
    QPushButton* m_loadMesh;
    QSpinBox* m_uvSet;
    QCheckBox* m_link;
    QComboBox* m_environment;
    SliderField* m_exposure;
    QCheckBox* m_showEnvironment;
    int m_builtIns = 0; // the combo's first items
};

} // namespace px::studio

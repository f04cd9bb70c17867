#pragma once
// Bake ▸ From Mesh…: the mesh (read when chosen, with its up axis), its bounds, the tile (the
// bounds by default), the maps' size, sub-samples, height range, wrap, which maps, and the
// occlusion rays. The window reads the mesh through `reader` (in the background) and bakes what
// options() says once the dialog is accepted.

#include "jobs/MeshBakeJob.h"

#include <QDialog>
#include <functional>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace px::studio {

class MeshBakeDialog : public QDialog {
    Q_OBJECT
public:
    // Reads a mesh (path, up axis); a null result with an error shown by the reader, or nothing
    // when cancelled.
    using Reader = std::function<SharedBakeMesh(const QString& path, MeshUp up)>;
    // Asks for a mesh file; empty when cancelled.
    using Chooser = std::function<QString()>;

    MeshBakeDialog(Reader reader, Chooser chooser, QWidget* parent = nullptr);

    // Reads `path` as the mesh to bake (what Choose… does after the file dialog).
    void setMesh(const QString& path);
    const SharedBakeMesh& mesh() const { return m_mesh; }
    QString meshPath() const { return m_path; }
    MeshBakeOptions options() const;
    QString boundsText() const;

private:
    void readMesh();
    void resetTile();
    void updateEnabled();

    Reader m_reader;
    Chooser m_chooser;
    SharedBakeMesh m_mesh;
    QString m_path;
    QLineEdit* m_file;
    QComboBox* m_up;
    QLabel* m_bounds;
    QDoubleSpinBox* m_tile[4];
    QComboBox* m_size;
    QSpinBox* m_samples;
    QCheckBox* m_hitRange;
    QDoubleSpinBox* m_z0;
    QDoubleSpinBox* m_z1;
    QComboBox* m_wrap;
    QCheckBox* m_height;
    QCheckBox* m_normal;
    QCheckBox* m_occlusion;
    QSpinBox* m_rays;
    QDoubleSpinBox* m_distance;
    QDialogButtonBox* m_buttons;
};

} // namespace px::studio

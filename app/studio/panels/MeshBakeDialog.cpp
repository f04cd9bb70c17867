#include "panels/MeshBakeDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <cfloat>
#include <limits>

namespace px::studio {

namespace {

QDoubleSpinBox* coordinate(QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(-1e9, 1e9);
    box->setDecimals(4);
    box->setMinimumWidth(80);
    return box;
}

} // namespace

MeshBakeDialog::MeshBakeDialog(Reader reader, Chooser chooser, QWidget* parent)
    : QDialog(parent), m_reader(std::move(reader)), m_chooser(std::move(chooser)) {
    setWindowTitle(tr("Bake from Mesh"));
    setObjectName(QStringLiteral("mesh-bake-dialog"));
    auto* form = new QFormLayout;

    m_file = new QLineEdit(this);
    m_file->setReadOnly(true);
    m_file->setPlaceholderText(tr("OBJ, PLY, STL, glTF/GLB or FBX"));
    auto* choose = new QPushButton(tr("Choose…"), this);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(choose);
    form->addRow(tr("Mesh"), fileRow);
    m_up = new QComboBox(this);
    m_up->addItem(tr("Z up (seen from +Z)"));
    m_up->addItem(tr("Y up (seen from +Y, −Z at the top)"));
    form->addRow(tr("Up axis"), m_up);
    m_bounds = new QLabel(tr("no mesh yet"), this);
    m_bounds->setObjectName(QStringLiteral("mesh-bounds"));
    m_bounds->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(tr("Bounds"), m_bounds);

    auto* tileRow = new QHBoxLayout;
    for (QDoubleSpinBox*& box : m_tile) {
        box = coordinate(this);
        tileRow->addWidget(box);
    }
    auto* bounds = new QPushButton(tr("Bounds"), this);
    bounds->setToolTip(tr("The tile: the mesh's XY bounds."));
    tileRow->addWidget(bounds);
    form->addRow(tr("Tile x0, y0, x1, y1"), tileRow);

    m_size = new QComboBox(this);
    for (int size : {256, 512, 1024, 2048, 4096})
        m_size->addItem(QStringLiteral("%1 × %1").arg(size), size);
    m_size->setCurrentIndex(2);
    form->addRow(tr("Size"), m_size);
    m_samples = new QSpinBox(this);
    m_samples->setRange(1, 8);
    m_samples->setSuffix(tr(" × K sub-samples"));
    m_samples->setToolTip(tr("K × K rays a texel, averaged."));
    form->addRow(tr("Samples K"), m_samples);

    m_hitRange = new QCheckBox(tr("the range of the hits"), this);
    m_hitRange->setChecked(true);
    m_z0 = coordinate(this);
    m_z1 = coordinate(this);
    m_z1->setValue(1.0);
    auto* rangeRow = new QHBoxLayout;
    rangeRow->addWidget(m_hitRange);
    rangeRow->addWidget(m_z0);
    rangeRow->addWidget(m_z1);
    form->addRow(tr("Height range"), rangeRow);

    m_wrap = new QComboBox(this);
    m_wrap->addItem(tr("repeat (seamless: the mesh's copies around it)"));
    m_wrap->addItem(tr("clamp (the mesh alone)"));
    form->addRow(tr("Wrap"), m_wrap);

    m_height = new QCheckBox(tr("Height"), this);
    m_normal = new QCheckBox(tr("Normal"), this);
    m_occlusion = new QCheckBox(tr("Occlusion"), this);
    auto* mapsRow = new QHBoxLayout;
    for (QCheckBox* box : {m_height, m_normal, m_occlusion}) {
        box->setChecked(true);
        mapsRow->addWidget(box);
    }
    form->addRow(tr("Maps"), mapsRow);
    m_rays = new QSpinBox(this);
    m_rays->setRange(1, 4096);
    m_rays->setValue(64);
    form->addRow(tr("Occlusion rays"), m_rays);
    m_distance = new QDoubleSpinBox(this);
    m_distance->setRange(0.0, 1e9);
    m_distance->setDecimals(4);
    m_distance->setSpecialValueText(tr("unlimited"));
    form->addRow(tr("Occlusion distance"), m_distance);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Bake"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_buttons);

    connect(choose, &QPushButton::clicked, this, [this] {
        const QString path = m_chooser ? m_chooser() : QString();
        if (!path.isEmpty())
            setMesh(path);
    });
    connect(m_up, &QComboBox::currentIndexChanged, this, [this] { readMesh(); });
    connect(bounds, &QPushButton::clicked, this, &MeshBakeDialog::resetTile);
    connect(m_hitRange, &QCheckBox::toggled, this, &MeshBakeDialog::updateEnabled);
    for (QCheckBox* box : {m_height, m_normal, m_occlusion})
        connect(box, &QCheckBox::toggled, this, &MeshBakeDialog::updateEnabled);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    updateEnabled();
}

void MeshBakeDialog::setMesh(const QString& path) {
    m_path = path;
    m_file->setText(QFileInfo(path).fileName());
    m_file->setToolTip(path);
    readMesh();
}

void MeshBakeDialog::readMesh() {
    m_mesh.reset();
    if (!m_path.isEmpty() && m_reader)
        m_mesh = m_reader(m_path, m_up->currentIndex() == 1 ? MeshUp::Y : MeshUp::Z);
    m_bounds->setText(boundsText());
    resetTile();
    updateEnabled();
}

QString MeshBakeDialog::boundsText() const {
    if (!m_mesh)
        return tr("no mesh yet");
    const BakeMesh& m = *m_mesh;
    return tr("%1 triangles; X %2 to %3, Y %4 to %5, Z %6 to %7")
        .arg(m.triangleCount())
        .arg(m.lo.x)
        .arg(m.hi.x)
        .arg(m.lo.y)
        .arg(m.hi.y)
        .arg(m.lo.z)
        .arg(m.hi.z);
}

void MeshBakeDialog::resetTile() {
    if (!m_mesh)
        return;
    const BakeTile t = defaultTile(*m_mesh);
    const double values[4] = {t.x0, t.y0, t.x1, t.y1};
    for (int i = 0; i < 4; ++i)
        m_tile[i]->setValue(values[i]);
    m_z0->setValue(m_mesh->lo.z);
    m_z1->setValue(m_mesh->hi.z);
}

void MeshBakeDialog::updateEnabled() {
    m_z0->setEnabled(!m_hitRange->isChecked());
    m_z1->setEnabled(!m_hitRange->isChecked());
    m_rays->setEnabled(m_occlusion->isChecked());
    m_distance->setEnabled(m_occlusion->isChecked());
    const bool anyMap = m_height->isChecked() || m_normal->isChecked() || m_occlusion->isChecked();
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(m_mesh != nullptr && anyMap);
}

MeshBakeOptions MeshBakeDialog::options() const {
    MeshBakeOptions o;
    o.tile = {m_tile[0]->value(), m_tile[1]->value(), m_tile[2]->value(), m_tile[3]->value()};
    o.width = o.height = m_size->currentData().toInt();
    o.samples = m_samples->value();
    if (!m_hitRange->isChecked())
        o.range = HeightRangeZ{m_z0->value(), m_z1->value()};
    o.wrap = m_wrap->currentIndex() == 0 ? WrapMode::Repeat : WrapMode::Clamp;
    o.maps = {m_height->isChecked(), m_normal->isChecked(), m_occlusion->isChecked()};
    o.rays = m_rays->value();
    if (m_distance->value() > 0.0)
        o.distance = m_distance->value();
    return o;
}

} // namespace px::studio

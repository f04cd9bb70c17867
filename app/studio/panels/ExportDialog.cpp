#include "panels/ExportDialog.h"

#include "widgets/FileDialogs.h"
#include "widgets/OcclusionDistanceBox.h"

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
#include <QScreen>
#include <QScrollArea>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>

namespace px::studio {

ExportDialog::ExportDialog(const Material& material, const QString& materialFile, QWidget* parent)
    : QDialog(parent), m_material(material), m_materialFile(materialFile) {
    setWindowTitle(tr("Export Material"));
    m_format = new QComboBox(this);
    for (std::string_view name : exportFormatNames())
        m_format->addItem(QString::fromUtf8(name.data(), static_cast<int>(name.size())));
    m_format->setToolTip(tr("package: the material, the maps its technique reads and its "
                            "specialised shader. gltf, godot: ready-made materials. unreal, "
                            "unity: textures named and packed as those engines expect."));
    const QFileInfo file(materialFile);
    m_folder = new QLineEdit(file.absolutePath() + QLatin1Char('/') + file.completeBaseName() +
                                 QStringLiteral("-export"),
                             this);
    auto* browse = new QToolButton(this);
    browse->setText(tr("…"));
    browse->setToolTip(tr("Choose the folder to export into."));
    m_folder->setToolTip(tr("The export's own folder: created, or replaced when it holds an "
                            "earlier export and \"Replace\" is ticked."));
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);
    m_height = new QComboBox(this);
    m_height->addItem(tr("16-bit PNG"), static_cast<int>(PixelFormat::UInt16));
    m_height->addItem(tr("float EXR"), static_cast<int>(PixelFormat::Float));
    m_normal = new QComboBox(this);
    m_normal->addItem(tr("8-bit PNG"), static_cast<int>(PixelFormat::UInt8));
    m_normal->addItem(tr("16-bit PNG"), static_cast<int>(PixelFormat::UInt16));
    m_green = new QComboBox(this);
    m_green->addItem(tr("OpenGL (Y+)"), static_cast<int>(NormalGreen::OpenGL));
    m_green->addItem(tr("DirectX (Y-)"), static_cast<int>(NormalGreen::DirectX));
    m_green->setToolTip(tr("Green of the package's normal map. Engine targets use their own "
                           "(Unreal: DirectX, the others: OpenGL)."));
    m_force = new QCheckBox(tr("Replace a previous export in this folder"), this);
    m_force->setToolTip(tr("Only a folder that is empty or that an export wrote is replaced, "
                           "never a folder of other files."));
    m_bakeOcclusion = new QCheckBox(tr("Bake ambient occlusion where the material has none"), this);
    m_bakeOcclusion->setToolTip(tr("Bake an occlusion map from the height map for the formats "
                                   "that have a slot for one (glTF, Godot, Unreal, Unity, the "
                                   "package); a loaded or baked occlusion map goes out as it is."));
    m_occlusionDistance = makeOcclusionDistanceBox(this);
    m_occlusionDistance->setEnabled(false);
    connect(m_bakeOcclusion, &QCheckBox::toggled, m_occlusionDistance, &QWidget::setEnabled);
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("export-result"));
    m_result->setWordWrap(true);
    m_result->setTextFormat(Qt::PlainText);
    m_result->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_result->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    // The result's lines (files, then notes such as "self-shadowing is not exported") scroll
    // when the dialog cannot grow to hold them all; it grows first (showResult).
    m_resultArea = new QScrollArea(this);
    m_resultArea->setWidget(m_result);
    m_resultArea->setWidgetResizable(true);
    m_resultArea->setFrameShape(QFrame::NoFrame);
    m_resultArea->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

    auto* form = new QFormLayout;
    form->addRow(tr("Format"), m_format);
    form->addRow(tr("Folder"), folderRow);
    form->addRow(tr("Height map"), m_height);
    form->addRow(tr("Normal map"), m_normal);
    form->addRow(tr("Package normal green"), m_green);
    form->addRow(QString(), m_force);
    form->addRow(QString(), m_bakeOcclusion);
    form->addRow(tr("Occlusion distance"), m_occlusionDistance);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_export = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_resultArea, 1);
    layout->addWidget(buttons);

    connect(browse, &QToolButton::clicked, this, [this] {
        // Pick where the export goes; the export is a new folder in there, named after the file.
        const QFileInfo current(m_folder->text());
        const QString parent =
            askFolder(this, FileKind::ExportFolder, tr("Export Into"), current.absolutePath());
        if (!parent.isEmpty())
            m_folder->setText(parent + QLatin1Char('/') + current.fileName());
    });
    connect(m_format, &QComboBox::currentTextChanged, this, [this](const QString& format) {
        m_green->setEnabled(format == QLatin1String("package"));
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_export, &QPushButton::clicked, this, &ExportDialog::startExport);
    connect(&m_watcher, &QFutureWatcher<Result<ExportResult>>::finished, this, [this] {
        const Result<ExportResult> result = m_watcher.result();
        m_export->setEnabled(true);
        if (!result) {
            // The core speaks the command line's language; here the option is a check box.
            QString message = QString::fromStdString(result.error().message);
            message.replace(QStringLiteral("use --force to replace it"),
                            tr("tick \"%1\" to replace it").arg(m_force->text()));
            message.replace(QStringLiteral("even with --force"), tr("even when asked to"));
            showResult(message);
            emit exportFinished(false);
            return;
        }
        QStringList lines;
        lines << tr("Exported to %1:").arg(QString::fromStdString(result->folder));
        for (const std::string& f : result->files)
            lines << QStringLiteral("  ") + QString::fromStdString(f);
        for (const std::string& n : result->notes)
            lines << QString::fromStdString(n);
        if (!result->kept.empty()) {
            QStringList kept;
            for (const std::string& f : result->kept)
                kept << QString::fromStdString(f);
            lines << tr("Kept %n file(s) this export did not write: %1", nullptr,
                        static_cast<int>(kept.size()))
                         .arg(kept.join(QStringLiteral(", ")));
        }
        showResult(lines.join(QLatin1Char('\n')));
        emit exportFinished(true);
    });
}

ExportOptions ExportDialog::options() const {
    ExportOptions o;
    o.format =
        parseExportFormat(m_format->currentText().toStdString()).value_or(ExportFormat::Package);
    o.outDir = m_folder->text().toStdString();
    o.force = m_force->isChecked();
    o.heightFormat = static_cast<PixelFormat>(m_height->currentData().toInt());
    o.normalFormat = static_cast<PixelFormat>(m_normal->currentData().toInt());
    o.packageGreen = static_cast<NormalGreen>(m_green->currentData().toInt());
    o.bakeOcclusion = m_bakeOcclusion->isChecked();
    o.occlusionDistance = occlusionDistanceOf(m_occlusionDistance);
    return o;
}

void ExportDialog::showResult(const QString& text) {
    m_result->setText(text);
    // Grow to hold the whole result, as far as the screen allows; the rest scrolls.
    const int width = m_resultArea->viewport()->width();
    const int wanted = m_result->heightForWidth(width) - m_resultArea->viewport()->height();
    if (wanted <= 0 || !isVisible())
        return;
    const QRect room = screen() ? screen()->availableGeometry() : QRect();
    const int frame = frameGeometry().height() - height();
    const int most = room.isValid() ? room.height() - frame : height() + wanted;
    const int grown = std::min(height() + wanted, most);
    if (grown <= height())
        return;
    resize(this->width(), grown);
    // Kept on the screen: its top moves up where its bottom would leave it.
    if (room.isValid() && frameGeometry().bottom() > room.bottom())
        move(x(), std::max(room.top(), y() - (frameGeometry().bottom() - room.bottom())));
}

QString ExportDialog::resultText() const {
    return m_result->text();
}

void ExportDialog::startExport() {
    if (m_watcher.isRunning())
        return;
    m_export->setEnabled(false);
    showResult(tr("Exporting…"));
    const Material material = m_material;
    const std::string file = m_materialFile.toStdString();
    const ExportOptions opts = options();
    m_watcher.setFuture(
        QtConcurrent::run([material, file, opts] { return exportMaterial(material, file, opts); }));
}

} // namespace px::studio

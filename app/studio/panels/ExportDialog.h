#pragma once
// Export: where to (the project's package, glTF, Godot, Unreal, Unity), into which folder, at
// which bit depths. Runs in the background; never overwrites a folder unless asked to replace a
// previous export.

#include "parallax/export/Exporter.h"

#include <QDialog>
#include <QFutureWatcher>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QScrollArea;

namespace px::studio {

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // `material` with absolute map paths; `materialFile` where it is saved.
    ExportDialog(const Material& material, const QString& materialFile, QWidget* parent = nullptr);

    ExportOptions options() const;
    void startExport();
    QString resultText() const;
    // The result's scroll area: every note is in it, in view or a scroll away (tests).
    QScrollArea* resultArea() const { return m_resultArea; }
    QCheckBox* bakeOcclusionBox() const { return m_bakeOcclusion; }
    bool isRunning() const { return m_watcher.isRunning(); }

signals:
    void exportFinished(bool ok);

private:
    Material m_material;
    QString m_materialFile;
    QComboBox* m_format;
    QLineEdit* m_folder;
    QComboBox* m_height;
    QComboBox* m_normal;
    QComboBox* m_green;
    QCheckBox* m_force;
    void showResult(const QString& text);

    QCheckBox* m_bakeOcclusion;
    QDoubleSpinBox* m_occlusionDistance;
    QLabel* m_result;
    QScrollArea* m_resultArea;
    QPushButton* m_export;
    QFutureWatcher<Result<ExportResult>> m_watcher;
};

} // namespace px::studio

#pragma once
// Compare: runs the bench (every technique over its quality sweep, against the exact intersection)
// on the current material in the background, then shows the work-precision plot. Clicking a
// point applies that technique and setting to the active viewport.

#include "parallax/eval/WorkPrecision.h"

#include <QWidget>
#include <optional>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace px::studio {

class BenchRunner;
class MaterialDocument;
class WorkPrecisionView;
struct BenchOutcome;

class ComparePanel : public QWidget {
    Q_OBJECT
public:
    ComparePanel(MaterialDocument* document, QWidget* parent = nullptr);

    void run();
    void cancel();
    bool isRunning() const;

    WorkPrecisionView* chartView() const { return m_chart; }
    QComboBox* polarCombo() const { return m_polar; }
    QComboBox* axisCombo() const { return m_axis; }
    QSpinBox* raysField() const { return m_rays; }
    QPushButton* runButton() const { return m_run; }
    QPushButton* cancelButton() const { return m_cancel; }
    QProgressBar* progressBar() const { return m_progress; }
    QString statusText() const; // the line under the controls
    const std::optional<WorkPrecisionChart>& chart() const { return m_result; }

signals:
    void settingChosen(px::Technique technique, const px::TraceParams& params);
    void finished(); // a run ended (done, failed or cancelled)

private:
    void showPanel();
    void onFinished(const BenchOutcome& outcome);

    MaterialDocument* m_document;
    BenchRunner* m_runner;
    QComboBox* m_polar;
    QComboBox* m_axis;
    QSpinBox* m_rays;
    QPushButton* m_run;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    WorkPrecisionView* m_chart;
    std::optional<WorkPrecisionChart> m_result;
};

} // namespace px::studio

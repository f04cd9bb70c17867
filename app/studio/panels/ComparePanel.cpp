#include "panels/ComparePanel.h"

#include "jobs/BenchRunner.h"
#include "jobs/EditorGpuTimer.h"
#include "model/MaterialDocument.h"
#include "panels/WorkPrecisionView.h"
#include "parallax/eval/QualitySweep.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace px::studio {

ComparePanel::ComparePanel(MaterialDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_runner(new BenchRunner(this)) {
    m_polar = new QComboBox(this);
    m_polar->setToolTip(tr("The view angle from the surface normal: grazing views (80°, 87°) are "
                           "where the cheap techniques fall apart."));
    m_axis = new QComboBox(this);
    m_axis->setToolTip(tr("Cost: height fetches per ray (deterministic), measured CPU time per "
                          "ray, or GPU milliseconds per 1920 x 1080 rays on this machine's GPU "
                          "(timer queries; a steady clock around glFinish on software "
                          "renderers)."));
    m_axis->setSizeAdjustPolicy(QComboBox::AdjustToContents); // never cut the axis's name
    m_axis->setMinimumContentsLength(12);
    // Below the views the dock is as wide as they are: the layout must not squeeze the name.
    m_axis->setSizePolicy(QSizePolicy::Minimum, QSizePolicy::Fixed);
    m_rays = new QSpinBox(this);
    m_rays->setRange(8, 512);
    m_rays->setValue(64);
    // R × R rays: the field shows R, the label says what it counts (not "64 rays").
    m_rays->setSuffix(tr(" per side"));
    m_rays->setToolTip(tr("R: R × R rays per view angle (the canonical trace scene), 64 gives "
                          "4096 rays. More rays, steadier percentiles, longer run."));
    m_run = new QPushButton(tr("Run"), this);
    m_run->setToolTip(tr("Measure every technique on this material's height map and height "
                         "scale (Ctrl+R). Runs in the background."));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setEnabled(false);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_status = new QLabel(this);
    m_status->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_chart = new WorkPrecisionView(this);

    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("View angle"), this));
    controls->addWidget(m_polar);
    controls->addWidget(new QLabel(tr("Cost"), this));
    controls->addWidget(m_axis);
    controls->addWidget(new QLabel(tr("Rays"), this));
    controls->addWidget(m_rays);
    controls->addWidget(m_run);
    controls->addWidget(m_cancel);
    controls->addWidget(m_progress, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(controls);
    layout->addWidget(m_status);
    layout->addWidget(m_chart, 1);

    connect(m_run, &QPushButton::clicked, this, &ComparePanel::run);
    connect(m_cancel, &QPushButton::clicked, this, &ComparePanel::cancel);
    connect(m_polar, &QComboBox::currentIndexChanged, this, &ComparePanel::showPanel);
    connect(m_axis, &QComboBox::currentIndexChanged, this, &ComparePanel::showPanel);
    connect(m_runner, &BenchRunner::progress, this,
            [this](int done, int total, const QString& stage) {
                m_progress->setRange(0, std::max(1, total));
                m_progress->setValue(done);
                m_status->setText(stage);
            });
    connect(m_runner, &BenchRunner::finished, this, &ComparePanel::onFinished);
    connect(m_chart, &WorkPrecisionView::pointClicked, this, [this](const WorkPrecisionPoint& p) {
        emit settingChosen(p.setting.technique, p.setting.params);
    });
    // A result describes the material it was measured on: a new height map makes it stale.
    connect(document, &MaterialDocument::changed, this, [this](MaterialDocument::Changes what) {
        if (m_result && (what & (MaterialDocument::MapsChanged | MaterialDocument::FileChanged)))
            m_status->setText(tr("The maps changed since this comparison: run it again."));
    });
}

QString ComparePanel::statusText() const {
    return m_status->text();
}

bool ComparePanel::isRunning() const {
    return m_runner->isRunning();
}

void ComparePanel::run() {
    if (m_runner->isRunning())
        return;
    const DocumentState& s = m_document->state();
    if (!s.hasMap(MapKind::Height)) {
        m_status->setText(tr("Load a height map first."));
        return;
    }
    if (!(s.material.heightScale > 0.0f)) {
        m_status->setText(tr("The height scale is 0: every technique returns the surface itself."));
        return;
    }
    BenchConfig config;
    config.maps.push_back({s.material.name, std::make_shared<const HeightField>(s.assets->height)});
    config.wrap = s.material.wrap;
    for (const TechniqueInfo& t : allTechniques()) {
        if (!t.parallax || t.id == Technique::Offset)
            continue;
        for (BenchSetting& setting : qualitySweep(t.id))
            config.settings.push_back(std::move(setting));
    }
    config.scales = {s.material.heightScale};
    config.rays = m_rays->value();
    config.timingRepeats = 1;
    // GPU ms on the GPU that draws the viewports (EditorGpuTimer.h), with the production kernels
    // as the viewports draw them. Software renderers time 128 x 128 rays and scale them to the
    // 1920 x 1080 frame (the label says so).
    GpuBenchOptions gpu;
    gpu.softwareRays = 128;
    config.gpuTimer = editorGpuTimer(gpu);
    if (Status ok = validate(config); !ok) {
        m_status->setText(QString::fromStdString(ok.error().message));
        return;
    }
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
    m_progress->setRange(0, 0); // busy until the first progress report
    m_status->setText(tr("Measuring %1 settings at 4 view angles…").arg(config.settings.size()));
    m_chart->setPlaceholderText(
        tr("Measuring every technique's error and cost on this material: the plot shows here "
           "when it is done (progress above, Cancel stops it)."));
    m_runner->start(std::move(config));
}

void ComparePanel::cancel() {
    m_runner->cancel();
}

void ComparePanel::onFinished(const BenchOutcome& outcome) {
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
    m_progress->setRange(0, 1);
    m_progress->setValue(outcome.report ? 1 : 0);
    if (outcome.cancelled) {
        m_status->setText(tr("Cancelled."));
        m_chart->setPlaceholderText(tr("The comparison was cancelled. Run it again (Ctrl+R) to "
                                       "measure every technique's error against its cost."));
    } else if (!outcome.error.isEmpty()) {
        m_status->setText(outcome.error);
        m_chart->setPlaceholderText(tr("The comparison failed (the line above says why)."));
    } else if (outcome.report) {
        m_result = makeWorkPrecisionChart(*outcome.report);
        const QSignalBlocker a(m_polar), b(m_axis);
        const int polar = std::max(0, m_polar->currentIndex());
        m_polar->clear();
        for (double angle : m_result->polarDeg)
            m_polar->addItem(QStringLiteral("%1°").arg(angle));
        m_polar->setCurrentIndex(std::min(polar == 0 ? 2 : polar, m_polar->count() - 1));
        m_axis->clear();
        for (CostAxis axis : m_result->axes)
            m_axis->addItem(QString::fromUtf8(costAxisTitle(axis).data()), static_cast<int>(axis));
        // Not "%2²": QString::arg reads the superscript two as a digit (placeholder 22).
        m_status->setText(tr("Measured in %1 s against the exact intersection, %2 × %2 rays per "
                             "view angle. Click a point to use it in the active viewport. GPU: %3")
                              .arg(outcome.seconds, 0, 'f', 1)
                              .arg(outcome.report->rays)
                              .arg(QString::fromStdString(outcome.report->gpuNote)));
        showPanel();
    }
    emit finished();
}

void ComparePanel::showPanel() {
    if (!m_result || m_polar->currentIndex() < 0 || m_axis->currentIndex() < 0) {
        m_chart->clear();
        return;
    }
    m_chart->setPanel(m_result->panel(static_cast<std::size_t>(m_polar->currentIndex()),
                                      static_cast<std::size_t>(m_axis->currentIndex())));
}

} // namespace px::studio

#include "panels/TechniquePanel.h"

#include "jobs/BackgroundLoad.h"
#include "model/MaterialDocument.h"
#include "panels/WorkPrecisionView.h"
#include "parallax/eval/AutoTechnique.h"
#include "parallax/eval/WorkPrecision.h"
#include "widgets/Hints.h"
#include "widgets/RangeSlider.h"
#include "widgets/SliderField.h"
#include "widgets/TechniqueCombo.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace px::studio {

int layersForQuality(double quality) {
    return std::clamp(static_cast<int>(std::lround(quality * 50.0)), 1, kMaxLayersLimit);
}

double qualityForLayers(int layers) {
    return layers / 50.0;
}

TechniquePanel::TechniquePanel(MaterialDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    m_box = new QGroupBox(this);
    outer->addWidget(m_box);
    auto* layout = new QVBoxLayout(m_box);

    m_technique = new TechniqueCombo(this);
    auto* form = new QFormLayout;
    form->addRow(tr("Technique"), m_technique);
    layout->addLayout(form);

    m_minLayers = new SliderField(tr("Min layers"), {1, 64, 1, kMaxLayersLimit, 0, 1}, this);
    m_maxLayers = new SliderField(tr("Max layers"), {1, 128, 1, kMaxLayersLimit, 0, 1}, this);
    m_minLayers->setHint(hints::minLayers());
    m_maxLayers->setHint(hints::maxLayers());

    m_qualityRow = new QWidget(this);
    auto* qualityLayout = new QHBoxLayout(m_qualityRow);
    qualityLayout->setContentsMargins(0, 0, 0, 0);
    auto* qualityLabel = new QLabel(tr("Quality range"), m_qualityRow);
    m_quality = new RangeSlider(m_qualityRow);
    m_qualityLow = new QDoubleSpinBox(m_qualityRow);
    m_qualityHigh = new QDoubleSpinBox(m_qualityRow);
    for (QDoubleSpinBox* box : {m_qualityLow, m_qualityHigh}) {
        box->setRange(0.02, kMaxLayersLimit / 50.0);
        box->setDecimals(2);
        box->setSingleStep(0.02);
        box->setKeyboardTracking(false);
    }
    qualityLayout->addWidget(qualityLabel, 3);
    qualityLayout->addWidget(m_qualityLow, 2);
    qualityLayout->addWidget(m_quality, 3);
    qualityLayout->addWidget(m_qualityHigh, 2);
    for (QWidget* w : {static_cast<QWidget*>(qualityLabel), static_cast<QWidget*>(m_quality),
                       static_cast<QWidget*>(m_qualityLow), static_cast<QWidget*>(m_qualityHigh)}) {
        w->setToolTip(hints::qualityRange());
        w->setStatusTip(hints::qualityRange());
    }

    m_binary = new SliderField(tr("Binary steps"), {0, 16, 0, kMaxRefineLimit, 0, 1}, this);
    m_secant = new SliderField(tr("Secant steps"), {0, 16, 0, kMaxRefineLimit, 0, 1}, this);
    m_cap = new SliderField(tr("Step cap"), {1, 256, 1, kMaxStepsLimit, 0, 1}, this);
    m_binary->setHint(hints::binarySteps());
    m_secant->setHint(hints::secantSteps());

    m_defaults = new QPushButton(tr("Defaults"), this);
    m_defaults->setToolTip(tr("The technique's default quality."));
    m_useForMaterial = new QPushButton(tr("Use for material"), this);
    m_useForMaterial->setToolTip(
        tr("Make this viewport's technique and quality the material's (viewport 1, saved)."));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_defaults);
    buttons->addWidget(m_useForMaterial);
    buttons->addStretch();

    for (QWidget* w : {static_cast<QWidget*>(m_minLayers), static_cast<QWidget*>(m_maxLayers),
                       m_qualityRow, static_cast<QWidget*>(m_binary),
                       static_cast<QWidget*>(m_secant), static_cast<QWidget*>(m_cap)})
        layout->addWidget(w);
    layout->addLayout(buttons);

    // Auto (the material's technique only): the cheapest setting meeting an error budget over
    // the view range, measured on this height map (parallax/eval/AutoTechnique.h), as render and
    // export resolve a material file's "auto".
    m_autoBox = new QGroupBox(tr("Auto: the cheapest setting within a budget"), this);
    auto* autoLayout = new QVBoxLayout(m_autoBox);
    auto* autoForm = new QFormLayout;
    m_autoBudget = new QDoubleSpinBox(m_autoBox);
    m_autoBudget->setRange(0.01, 100.0);
    m_autoBudget->setDecimals(2);
    m_autoBudget->setSingleStep(0.05);
    m_autoBudget->setValue(0.5);
    m_autoBudget->setSuffix(tr(" texel"));
    m_autoBudget->setToolTip(tr("The error allowed: p99 of the hits' distance from the exact "
                                "intersection, in texels, at every view angle up to the maximum."));
    m_autoPolar = new QDoubleSpinBox(m_autoBox);
    m_autoPolar->setRange(1.0, 89.0);
    m_autoPolar->setDecimals(1);
    m_autoPolar->setValue(80.0);
    m_autoPolar->setSuffix(QStringLiteral("°"));
    m_autoPolar->setToolTip(tr("The steepest view of the scene, from the surface's normal."));
    m_autoPick = new QPushButton(tr("Pick"), m_autoBox);
    m_autoPick->setToolTip(tr("Measure the techniques on this height map and make the cheapest "
                              "one meeting the budget the material's (saved as \"auto\")."));
    m_autoStatus = new QLabel(m_autoBox);
    m_autoStatus->setWordWrap(true);
    m_autoStatus->setTextInteractionFlags(Qt::TextSelectableByMouse);
    autoForm->addRow(tr("Budget"), m_autoBudget);
    autoForm->addRow(tr("Up to"), m_autoPolar);
    autoForm->addRow(m_autoPick);
    autoLayout->addLayout(autoForm);
    // The result and its chart below the form, not in a row of it: a form row spanning both
    // columns kept the wrapped sentences to one line's height (the rest was cut off).
    autoLayout->addWidget(m_autoStatus);
    m_autoChart = new WorkPrecisionView(m_autoBox);
    m_autoChart->setMinimumHeight(180);
    m_autoChart->setMinimumWidth(160); // a small chart, not the Compare panel's: never widens it
    m_autoChart->setToolTip(tr("Every setting Pick measured, p99 error against mean fetches at the "
                               "steepest view; the ring is the choice, the dashed line the "
                               "Pareto front."));
    m_autoChart->hide();
    autoLayout->addWidget(m_autoChart);
    layout->addWidget(m_autoBox);
    connect(m_autoPick, &QPushButton::clicked, this, &TechniquePanel::pickAuto);

    connect(m_technique, &TechniqueCombo::techniqueChosen, this, [this](Technique t) {
        editQuality(tr("Technique %1").arg(QString::fromUtf8(info(t).name.data())), {},
                    [t](ViewQuality& q) {
                        if (q.technique != t)
                            q = {t, info(t).defaults};
                    });
    });
    auto bindInt = [this](SliderField* field, const QString& text, const QString& key,
                          int TraceParams::*member) {
        connect(field, &SliderField::valueEdited, this, [=, this](double v) {
            editQuality(text, key, [=](ViewQuality& q) {
                q.params.*member = static_cast<int>(std::lround(v));
                // Keep min <= max the way the user means it: the other end follows.
                if (member == &TraceParams::minLayers)
                    q.params.maxLayers = std::max(q.params.maxLayers, q.params.minLayers);
                if (member == &TraceParams::maxLayers)
                    q.params.minLayers = std::min(q.params.minLayers, q.params.maxLayers);
            });
        });
        connect(field, &SliderField::editFinished, m_document, &MaterialDocument::endMerge);
    };
    bindInt(m_minLayers, tr("Min layers"), QStringLiteral("minLayers"), &TraceParams::minLayers);
    bindInt(m_maxLayers, tr("Max layers"), QStringLiteral("maxLayers"), &TraceParams::maxLayers);
    bindInt(m_binary, tr("Binary steps"), QStringLiteral("binarySteps"), &TraceParams::binarySteps);
    bindInt(m_secant, tr("Secant steps"), QStringLiteral("secantSteps"), &TraceParams::secantSteps);
    bindInt(m_cap, tr("Step cap"), QStringLiteral("maxSteps"), &TraceParams::maxSteps);

    connect(m_quality, &RangeSlider::rangeEdited, this, &TechniquePanel::setQualityRange);
    connect(m_quality, &RangeSlider::editFinished, m_document, &MaterialDocument::endMerge);
    connect(m_qualityLow, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        setQualityRange(v, std::max(v, m_qualityHigh->value()));
        m_document->endMerge();
    });
    connect(m_qualityHigh, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        setQualityRange(std::min(v, m_qualityLow->value()), v);
        m_document->endMerge();
    });
    connect(m_defaults, &QPushButton::clicked, this, [this] {
        editQuality(tr("Default quality"), {},
                    [](ViewQuality& q) { q.params = info(q.technique).defaults; });
    });
    connect(m_useForMaterial, &QPushButton::clicked, this, [this] {
        const ViewQuality q = m_document->state().view(m_viewport);
        m_document->edit(tr("Use viewport %1 for the material").arg(m_viewport + 1),
                         [q](DocumentState& s) { s.setView(0, q); });
    });

    connect(document, &MaterialDocument::changed, this, &TechniquePanel::refresh);
    refresh();
}

void TechniquePanel::pickAuto() {
    const DocumentState& s = m_document->state();
    if (!s.hasMap(MapKind::Height)) {
        m_autoStatus->setText(tr("Load a height map first."));
        return;
    }
    Material material = s.material;
    AutoQuality quality;
    quality.budget = static_cast<float>(m_autoBudget->value());
    quality.maxPolar = static_cast<float>(m_autoPolar->value());
    material.autoQuality = quality;
    const std::shared_ptr<const MaterialAssets> assets = s.assets;
    const std::string source = material.name.empty() ? "the height map" : material.name;
    Result<ResolvedAuto> resolved = runInBackground<ResolvedAuto>(
        window(), tr("Measuring the techniques…"), [material, assets, source] {
            return resolveAutoTechnique(material, assets->height, assets->cone, assets->relaxedCone,
                                        source);
        });
    if (!resolved) {
        m_autoStatus->setText(resolved.error().cancelled()
                                  ? tr("Cancelled; nothing changed.")
                                  : QString::fromStdString(resolved.error().message));
        return;
    }
    const Material chosen = resolved->material;
    m_document->edit(tr("Auto technique"), [&](DocumentState& next) {
        next.material.technique = chosen.technique;
        next.material.params = chosen.params;
        next.material.autoQuality = quality; // still auto: export measures its own maps again
    });
    m_autoNote = QString::fromStdString(resolved->note);
    if (!m_autoNote.isEmpty() && !m_autoNote.endsWith(QLatin1Char('.')))
        m_autoNote += QLatin1Char('.'); // a sentence may follow
    if (resolved->recommendation) {
        std::optional<PointRef> chosenPoint;
        m_autoChart->setPanel(makeRecommendationPanel(*resolved->recommendation, &chosenPoint));
        m_autoChart->setHighlight(chosenPoint);
        if (chosenPoint)
            m_autoNote += resolved->recommendation->chosen.onFront
                              ? tr(" It lies on the Pareto front (ringed).")
                              : tr(" It lies off the Pareto front (ringed): a setting on it is "
                                   "cheaper but misses the budget at a gentler angle.");
    }
    refresh();
}

QString TechniquePanel::autoStatus() const {
    return m_autoStatus->text();
}

void TechniquePanel::setViewport(int index) {
    m_viewport = std::clamp(index, 0, kMaxViewports - 1);
    refresh();
}

void TechniquePanel::editQuality(const QString& text, const QString& key,
                                 const std::function<void(ViewQuality&)>& change) {
    const int viewport = m_viewport;
    m_document->edit(
        text,
        [&](DocumentState& s) {
            ViewQuality q = s.view(viewport);
            change(q);
            s.setView(viewport, q);
        },
        key.isEmpty() ? key : key + QString::number(viewport));
}

void TechniquePanel::setQualityRange(double low, double high) {
    editQuality(tr("Quality range"), QStringLiteral("quality"), [=](ViewQuality& q) {
        q.params.minLayers = layersForQuality(low);
        q.params.maxLayers = std::max(q.params.minLayers, layersForQuality(high));
    });
}

void TechniquePanel::refresh() {
    const DocumentState& s = m_document->state();
    const ViewQuality q = s.view(m_viewport);
    const TechniqueInfo& t = info(q.technique);
    m_box->setTitle(m_viewport == 0 ? tr("Viewport 1: the material's technique")
                                    : tr("Viewport %1 technique").arg(m_viewport + 1));
    m_technique->updateAvailability(s);
    m_technique->setTechnique(q.technique);
    m_minLayers->setValue(q.params.minLayers);
    m_maxLayers->setValue(q.params.maxLayers);
    m_binary->setValue(q.params.binarySteps);
    m_secant->setValue(q.params.secantSteps);
    m_cap->setValue(q.params.maxSteps);
    m_cap->setHint(hints::stepCap(q.technique));
    {
        const QSignalBlocker a(m_qualityLow), b(m_qualityHigh);
        m_qualityLow->setValue(qualityForLayers(q.params.minLayers));
        m_qualityHigh->setValue(qualityForLayers(q.params.maxLayers));
        m_quality->setRange(qualityForLayers(q.params.minLayers),
                            qualityForLayers(q.params.maxLayers));
    }
    m_minLayers->setVisible(t.usesLayers);
    m_maxLayers->setVisible(t.usesLayers);
    m_qualityRow->setVisible(t.usesLayers);
    m_binary->setVisible(t.usesBinarySteps);
    m_secant->setVisible(t.usesSecantSteps);
    m_cap->setVisible(t.usesMaxSteps);
    m_useForMaterial->setVisible(m_viewport != 0);

    m_autoBox->setVisible(m_viewport == 0);
    const std::optional<AutoQuality>& a = s.material.autoQuality;
    if (!a) {
        m_autoNote.clear();
        m_autoChart->clear();
        m_autoStatus->setText(tr("The technique is chosen by hand."));
    } else {
        const QSignalBlocker x(m_autoBudget), y(m_autoPolar);
        m_autoBudget->setValue(a->budgetTexels());
        m_autoPolar->setValue(a->maxPolar);
        m_autoStatus->setText(m_autoNote.isEmpty()
                                  ? tr("Auto, not measured here yet: Pick measures it.")
                                  : m_autoNote);
    }
    m_autoChart->setVisible(m_autoChart->hasPanel());
}

} // namespace px::studio

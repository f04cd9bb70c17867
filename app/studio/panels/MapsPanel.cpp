#include "panels/MapsPanel.h"

#include "jobs/Baking.h"
#include "model/MaterialDocument.h"
#include "panels/MapRow.h"
#include "widgets/OcclusionDistanceBox.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace px::studio {

MapsPanel::MapsPanel(MaterialDocument* document, BakeRunner* baker, QWidget* parent)
    : QWidget(parent), m_document(document), m_baker(baker) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    for (MapKind kind : kAllMapKinds) {
        const bool bakeable = kind == MapKind::Normal || kind == MapKind::Cone ||
                              kind == MapKind::RelaxedCone || kind == MapKind::Ao;
        auto* row = new MapRow(kind, bakeable, this);
        m_rows[kind] = row;
        layout->addWidget(row);
        connect(row, &MapRow::loadRequested, this, &MapsPanel::loadRequested);
        connect(row, &MapRow::fileDropped, this, &MapsPanel::fileDropped);
        connect(row, &MapRow::clearRequested, this, &MapsPanel::clearMap);
        connect(row, &MapRow::bakeRequested, this, [this](MapKind k) {
            emit bakeRequested(k == MapKind::Normal ? BakeKind::Normal
                               : k == MapKind::Cone ? BakeKind::Cone
                               : k == MapKind::Ao   ? BakeKind::Occlusion
                                                    : BakeKind::RelaxedCone);
        });
    }

    auto* bake = new QGroupBox(tr("Baking"), this);
    // As wide as the panel, whatever its fields would like: the rows set the panel's width.
    bake->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    auto* bakeLayout = new QVBoxLayout(bake);
    m_filter = new QComboBox(this);
    for (std::string_view name : normalFilterNames())
        m_filter->addItem(QString::fromUtf8(name.data(), static_cast<int>(name.size())));
    m_filter->setCurrentText(QStringLiteral("sobel"));
    // Narrow enough for the panel on a small screen (960 x 540 at scale 2).
    m_filter->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_filter->setMinimumContentsLength(6);
    m_filter->setToolTip(tr("Derivative filter of the normal bake: central (4 taps, sharpest), "
                            "Sobel or Scharr (3x3, smoother). Each gives the same strength."));
    connect(m_filter, &QComboBox::currentIndexChanged, this, &MapsPanel::refresh);
    auto* form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows); // a narrow panel: the field under its label
    form->addRow(tr("Normal filter"), m_filter);
    m_occlusionDistance = makeOcclusionDistanceBox(this);
    form->addRow(tr("Occlusion distance"), m_occlusionDistance);
    m_bakeLabel = new QLabel(tr("No bake running."), this);
    m_bakeLabel->setObjectName(QStringLiteral("bake-status"));
    // A long line ("Baked the relaxed cone map in 7.2 s on the CPU (the GPU, llvmpipe (LLVM 15.0.6,
    // 256 bits), is a software rasteriser...)") wraps within the panel's width, which its length
    // never sets: it used to widen the panel until every row's buttons scrolled out of view.
    m_bakeLabel->setWordWrap(true);
    m_bakeLabel->setTextFormat(Qt::PlainText);
    m_bakeLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 100);
    m_progress->setValue(0);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setEnabled(false);
    m_cancel->setToolTip(tr("Stop the bake (Esc). Nothing changes in the material."));
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(m_progress, 1);
    progressRow->addWidget(m_cancel);
    bakeLayout->addLayout(form);
    bakeLayout->addWidget(m_bakeLabel);
    bakeLayout->addLayout(progressRow);
    layout->addWidget(bake);
    layout->addStretch();

    connect(m_cancel, &QPushButton::clicked, m_baker, &BakeRunner::cancel);
    connect(m_baker, &BakeRunner::started, this, [this](BakeKind kind) {
        setBakeStatus(tr("Baking the %1…").arg(bakeTitle(kind)));
        m_progress->setValue(0);
        m_cancel->setEnabled(true);
        refresh();
    });
    connect(m_baker, &BakeRunner::cancelling, this, [this](BakeKind kind) {
        setBakeStatus(tr("Cancelling the %1 bake…").arg(bakeTitle(kind)));
        m_cancel->setEnabled(false);
    });
    connect(m_baker, &BakeRunner::progress, this,
            [this](BakeKind, double f) { m_progress->setValue(static_cast<int>(f * 100)); });
    connect(m_baker, &BakeRunner::finished, this, [this](const BakeOutcome& outcome) {
        setBakeStatus(outcome.cancelled
                          ? tr("The %1 bake was cancelled.").arg(bakeTitle(outcome.request.kind))
                      : !outcome.error.isEmpty() ? outcome.error
                                                 : tr("Baked the %1 in %2 s %3.")
                                                       .arg(bakeTitle(outcome.request.kind))
                                                       .arg(outcome.seconds, 0, 'f', 2)
                                                       .arg(bakeDevice(outcome)));
        m_progress->setValue(outcome.cancelled || !outcome.error.isEmpty() ? 0 : 100);
    });
    connect(m_baker, &BakeRunner::idle, this, [this] {
        m_cancel->setEnabled(false);
        refresh();
    });
    connect(document, &MaterialDocument::changed, this, &MapsPanel::refresh);
    refresh();
}

QString MapsPanel::bakeStatus() const {
    return m_bakeLabel->text();
}

void MapsPanel::setBakeStatus(const QString& text) {
    m_bakeLabel->setText(text);
    m_bakeLabel->setToolTip(text); // whole, where a word longer than the panel is cut
}

void MapsPanel::showBakeShown(BakeKind kind, double bakeSeconds, const QString& device,
                              double shownSeconds) {
    setBakeStatus(tr("Baked the %1 in %2 s %3, shown %4 s after Bake.")
                      .arg(bakeTitle(kind))
                      .arg(bakeSeconds, 0, 'f', 2)
                      .arg(device)
                      .arg(shownSeconds, 0, 'f', 2));
}

double MapsPanel::occlusionDistance() const {
    return occlusionDistanceOf(m_occlusionDistance);
}

NormalFilter MapsPanel::normalFilter() const {
    return parseNormalFilter(m_filter->currentText().toStdString()).value_or(NormalFilter::Sobel);
}

void MapsPanel::clearMap(MapKind kind) {
    m_document->edit(tr("Clear %1 map").arg(QString::fromUtf8(mapTitle(kind).data()).toLower()),
                     [kind](DocumentState& s) {
                         auto assets = std::make_shared<MaterialAssets>(*s.assets);
                         switch (kind) {
                         case MapKind::Albedo:
                             assets->albedo = {};
                             break;
                         case MapKind::Normal:
                             assets->normal = {};
                             break;
                         case MapKind::Cone:
                             assets->cone = {};
                             break;
                         case MapKind::RelaxedCone:
                             assets->relaxedCone = {};
                             break;
                         case MapKind::Ao:
                             assets->ao = {};
                             s.occlusionBake.reset();
                             break;
                         case MapKind::Roughness:
                             assets->roughness = {};
                             break;
                         case MapKind::Metallic:
                             assets->metallic = {};
                             break;
                         case MapKind::Specular:
                             assets->specular = {};
                             break;
                         case MapKind::Height:
                             return; // every technique reads it
                         }
                         s.assets = assets;
                         mapPath(s.material.maps, kind).clear();
                         s.setUnsaved(kind, false);
                         if (kind == MapKind::Normal) {
                             s.normalBake.reset();
                             if (s.material.normalSource == NormalSource::Map)
                                 s.material.normalSource = NormalSource::HeightCentral;
                         }
                         // A technique left without its cone map falls back to the march.
                         for (int v = 0; v < kMaxViewports; ++v) {
                             if (!s.canTrace(s.view(v).technique))
                                 s.setView(v, {Technique::Pom, info(Technique::Pom).defaults});
                         }
                     });
}

void MapsPanel::refresh() {
    const DocumentState& s = m_document->state();
    const bool height = s.hasMap(MapKind::Height);
    for (auto& [kind, row] : m_rows) {
        row->refresh(s);
        row->setBakeEnabled(height && !m_baker->isBusy());
    }
    m_rows.at(MapKind::Normal)->setWarning(staleNormalBake(s, normalFilter()));
    m_rows.at(MapKind::Ao)->setWarning(staleOcclusionBake(s));
}

} // namespace px::studio

#include "preview/Viewport.h"

#include "model/MaterialDocument.h"
#include "preview/PreviewPlaceholder.h"
#include "preview/PreviewWidget.h"
#include "widgets/Hints.h"
#include "widgets/ImageConvert.h"
#include "widgets/TechniqueCombo.h"

#include <QActionGroup>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMouseEvent>
#include <QToolButton>
#include <QVBoxLayout>

namespace px::studio {

QString Viewport::figuresExplained() {
    return tr("Frame time (CPU wall clock around the draw and glFinish) and mean height "
              "fetches per pixel. Two errors, in texels of the height map (99th percentile, "
              "mean, max): the technique's own, its hit against the exact hit on the same "
              "filtered surface it marches (the mip level of the pixel's footprint), which "
              "its settings change; and the filtering's, that exact hit against the exact "
              "hit on level 0, which no setting of the technique changes. Each pixel weighs "
              "the texture area it covers, as the bench's evenly spread rays do, so the "
              "figures do not follow the window's size, and at the bench's angle they are "
              "the bench's (Compare). The share of the area whose hit lies on another "
              "surface (more than 2 texels from the exact one): a little of it lifts the "
              "mean above the p99. Left out: pixels seen steeper than 89°, and pixels whose "
              "exact hit lies off the surface this view shows (near a mesh's silhouette).");
}

QString Viewport::figuresMeasure() {
    return tr("technique: its hit vs the exact hit on the mip level it reads · filtering: "
              "that level vs level 0 · weighted by texture area");
}

Viewport::Viewport(int index, MaterialDocument* document, const QString& liveReason,
                   QWidget* parent)
    : QFrame(parent), m_index(index), m_document(document) {
    setFrameShape(QFrame::StyledPanel);
    setLineWidth(2);
    setObjectName(QStringLiteral("viewport%1").arg(index + 1));

    m_title = new QLabel(QString::number(index + 1), this);
    m_title->setToolTip(tr("Viewport %1 (Alt+%1 makes it active)").arg(index + 1));
    m_technique = new TechniqueCombo(this);
    m_heatMap = new QToolButton(this);
    m_heatMap->setText(tr("Error"));
    m_heatMap->setCheckable(true);
    m_heatMap->setToolTip(hints::heatMap());
    m_heatMap->setStatusTip(hints::heatMap());
    // The arrow picks which error the map shows; the button turns it on and off.
    m_heatMap->setPopupMode(QToolButton::MenuButtonPopup);
    auto* heatModes = new QMenu(m_heatMap);
    auto* heatGroup = new QActionGroup(heatModes);
    m_heatTechnique = heatModes->addAction(tr("Technique error (vs exact on its mip level)"));
    m_heatFiltering = heatModes->addAction(tr("Filtering error (its mip level vs level 0)"));
    for (QAction* a : {m_heatTechnique, m_heatFiltering}) {
        a->setCheckable(true);
        heatGroup->addAction(a);
    }
    m_heatTechnique->setChecked(true);
    m_heatMap->setMenu(heatModes);
    m_wipe = new QToolButton(this);
    m_wipe->setText(tr("A|B"));
    m_wipe->setCheckable(true);
    m_wipe->setToolTip(hints::wipe());
    m_wipe->setStatusTip(hints::wipe());
    m_wipeTechnique = new TechniqueCombo(this);
    m_wipeTechnique->setToolTip(tr("The technique on the right of the A/B wipe."));
    m_wipeTechnique->setVisible(false);

    auto* header = new QHBoxLayout;
    header->setContentsMargins(4, 2, 4, 2);
    header->addWidget(m_title);
    header->addWidget(m_technique);
    header->addStretch();
    header->addWidget(m_heatMap);
    header->addWidget(m_wipe);
    header->addWidget(m_wipeTechnique);

    QWidget* content = nullptr;
    if (liveReason.isEmpty()) {
        m_preview = new PreviewWidget(this);
        content = m_preview;
        connect(m_preview, &PreviewWidget::activated, this, [this] { emit activated(m_index); });
        connect(m_preview, &PreviewWidget::cameraDragged, this,
                [this](const OrbitCamera& c) { emit cameraEdited(m_index, c); });
        connect(m_preview, &PreviewWidget::lightDragged, this,
                [this](const DirectionalLight& l) { emit lightEdited(m_index, l); });
        connect(m_preview, &PreviewWidget::wipeDragged, this,
                [this](float x) { editOverlays([x](ViewOverlays& o) { o.wipePosition = x; }); });
        connect(m_preview, &PreviewWidget::statsChanged, this, &Viewport::showStats);
    } else {
        m_placeholder = new PreviewPlaceholder(liveReason, this);
        content = m_placeholder;
    }
    content->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);

    m_stats = new QLabel(this);
    m_stats->setObjectName(QStringLiteral("figures"));
    m_stats->setTextFormat(Qt::RichText);
    m_stats->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Four lines, each cut to the view's width (whole in statsText and the tooltip): were the
    // view's size to follow the figures' text, every new figure would resize the views and
    // restart their frames (a 2-view window jumped 212 <-> 506 px as figures came and went).
    m_stats->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_stats->setText(QStringLiteral("<b>8</b><br>8<br>8<br>8"));
    m_stats->setFixedHeight(m_stats->sizeHint().height());
    m_stats->installEventFilter(this);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addLayout(header);
    layout->addWidget(content, 1);
    layout->addWidget(m_stats);

    connect(m_technique, &TechniqueCombo::techniqueChosen, this, [this](Technique t) {
        m_document->edit(tr("Viewport %1: %2").arg(m_index + 1).arg(info(t).name.data()),
                         [this, t](DocumentState& s) {
                             if (s.view(m_index).technique != t)
                                 s.setView(m_index, {t, info(t).defaults});
                         });
    });
    connect(m_heatMap, &QToolButton::toggled, this,
            [this](bool on) { editOverlays([on](ViewOverlays& o) { o.heatMap = on; }); });
    auto showMode = [this](HeatMode mode) {
        editOverlays([mode](ViewOverlays& o) {
            o.heatMode = mode;
            o.heatMap = true; // picking what to show shows it
        });
    };
    connect(m_heatTechnique, &QAction::triggered, this,
            [showMode] { showMode(HeatMode::Technique); });
    connect(m_heatFiltering, &QAction::triggered, this,
            [showMode] { showMode(HeatMode::Filtering); });
    connect(m_wipe, &QToolButton::toggled, this,
            [this](bool on) { editOverlays([on](ViewOverlays& o) { o.wipe = on; }); });
    connect(m_wipeTechnique, &TechniqueCombo::techniqueChosen, this,
            [this](Technique t) { editOverlays([t](ViewOverlays& o) { o.wipeTechnique = t; }); });
    connect(document, &MaterialDocument::changed, this, &Viewport::refresh);
    refresh();
}

void Viewport::setActive(bool active) {
    m_active = active;
    // The frame alone (by its name), so the labels inside keep their colours.
    setStyleSheet(
        active ? QStringLiteral("QFrame#%1 { border: 2px solid palette(highlight); }")
                     .arg(objectName())
               : QStringLiteral("QFrame#%1 { border: 2px solid transparent; }").arg(objectName()));
    QFont f = m_title->font();
    f.setBold(active);
    m_title->setFont(f);
}

void Viewport::setView(const SharedView& view) {
    m_view = view;
    pushScene();
}

void Viewport::setOverlays(const ViewOverlays& overlays) {
    m_overlays = overlays;
    m_heatMap->blockSignals(true);
    m_wipe->blockSignals(true);
    m_heatMap->setChecked(overlays.heatMap);
    (overlays.heatMode == HeatMode::Filtering ? m_heatFiltering : m_heatTechnique)
        ->setChecked(true);
    m_heatMap->setText(overlays.heatMode == HeatMode::Filtering ? tr("Filtering") : tr("Error"));
    m_wipe->setChecked(overlays.wipe);
    m_heatMap->blockSignals(false);
    m_wipe->blockSignals(false);
    m_wipeTechnique->setTechnique(overlays.wipeTechnique);
    m_wipeTechnique->setVisible(overlays.wipe);
    pushScene();
}

QAction* Viewport::heatModeAction(HeatMode mode) const {
    return mode == HeatMode::Filtering ? m_heatFiltering : m_heatTechnique;
}

void Viewport::editOverlays(const std::function<void(ViewOverlays&)>& change) {
    ViewOverlays next = m_overlays;
    change(next);
    setOverlays(next);
    emit overlaysEdited(m_index, next);
}

bool Viewport::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_stats && event->type() == QEvent::Resize)
        fitStats();
    return QFrame::eventFilter(watched, event);
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    emit activated(m_index);
    QFrame::mousePressEvent(event);
}

void Viewport::refresh() {
    const DocumentState& s = m_document->state();
    m_technique->updateAvailability(s);
    m_technique->setTechnique(s.view(m_index).technique);
    m_wipeTechnique->updateAvailability(s);
    m_wipeTechnique->setTechnique(m_overlays.wipeTechnique);
    if (m_placeholder) {
        const MaterialAssets& a = *s.assets;
        m_placeholder->setImage(!a.albedo.empty() ? toQImage(a.albedo, 256)
                                                  : toQImage(a.height, 256));
    }
    pushScene();
}

void Viewport::pushScene() {
    const DocumentState& s = m_document->state();
    PreviewScene scene;
    scene.material = s.material;
    scene.quality = s.view(m_index);
    scene.material.technique = scene.quality.technique;
    scene.material.params = scene.quality.params;
    scene.assets = s.assets;
    scene.view = m_view;
    scene.overlays = m_overlays;
    scene.traceable = s.canTrace(scene.quality.technique) &&
                      (!m_overlays.wipe || s.canTrace(m_overlays.wipeTechnique));
    if (m_preview)
        m_preview->setScene(scene);
    showStats();
}

QString Viewport::statsText() const {
    return QStringLiteral("<b>%1</b>").arg(m_figureName) + m_figures.join(QStringLiteral("<br>"));
}

void Viewport::showStats() {
    m_figureName = QString::fromUtf8(info(m_document->state().view(m_index).technique).name.data());
    m_figures = QStringList{QString()};
    if (m_preview) {
        const PreviewStats& st = m_preview->stats();
        if (st.frameMs > 0)
            m_figures[0] += tr(" · %1 ms").arg(st.frameMs, 0, 'f', 1);
        if (st.valid && st.pixels > 0) {
            m_figures[0] += tr(" · %1 fetches/px").arg(st.fetchesPerPixel, 0, 'f', 1);
            // The p99s first: the line is cut at the view's width.
            m_figures << tr("p99 texels: technique %1, filtering %2 · mean %3, %4 · max %5, %6")
                             .arg(st.p99Error, 0, 'f', 3)
                             .arg(st.filteringP99Error, 0, 'f', 3)
                             .arg(st.meanError, 0, 'f', 3)
                             .arg(st.filteringMeanError, 0, 'f', 3)
                             .arg(st.maxError, 0, 'f', 2)
                             .arg(st.filteringMaxError, 0, 'f', 2);
            QString third = tr("%1 % on another surface · %2 px")
                                .arg(100.0 * st.otherSurfaceShare, 0, 'f', 2)
                                .arg(QLocale().toString(st.pixels));
            if (st.area > 0.0)
                third += tr(" covering %1 tiles").arg(st.area, 0, 'g', 3);
            // What is left out (docs/meshes.md): said, so the figures' pixels are known.
            QStringList left;
            if (st.steepPixels > 0)
                left << tr("%1 px steeper than 89°").arg(st.steepPixels);
            if (st.offRegionPixels > 0)
                left << tr("%1 px whose exact hit is off the visible surface")
                            .arg(st.offRegionPixels);
            if (!left.isEmpty())
                third += tr(" · not counted: %1").arg(left.join(QStringLiteral(", ")));
            m_figures << third;
        } else
            m_figures << (st.valid ? tr("no surface in view") : tr("measuring the error…"))
                      << QString();
        m_figures << figuresMeasure();
    }
    fitStats();
}

void Viewport::fitStats() {
    // Each line cut to the label's width, the first after the technique's name in bold.
    const int width = m_stats->contentsRect().width();
    QFont bold = m_stats->font();
    bold.setBold(true);
    const QFontMetrics plain(m_stats->font()), strong(bold);
    const int nameWidth = strong.horizontalAdvance(m_figureName);
    QStringList shown;
    for (const QString& line : m_figures) {
        const bool first = shown.isEmpty();
        const int room = first ? width - nameWidth : width;
        QString fitted =
            room > 0 ? plain.elidedText(line, Qt::ElideRight, room).toHtmlEscaped() : QString();
        if (first)
            fitted.prepend(QStringLiteral("<b>%1</b>")
                               .arg(strong.elidedText(m_figureName, Qt::ElideRight, width)));
        shown << fitted;
    }
    m_stats->setText(shown.join(QStringLiteral("<br>")));
    m_stats->setToolTip(m_figureName + m_figures.join(QLatin1Char('\n')) + QStringLiteral("\n\n") +
                        figuresExplained());
}

} // namespace px::studio

#include "panels/MapRow.h"

#include "jobs/Baking.h"
#include "model/DocumentState.h"
#include "widgets/ImageConvert.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QLabel>
#include <QMimeData>
#include <QResizeEvent>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWindow>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <functional>

namespace px::studio {

namespace {
constexpr int kThumbnail = 40; // logical pixels; drawn at the screen's pixel ratio
int g_thumbnails = 0;

// Maps up to this many texels (1024²) get their thumbnail at once, bigger ones from a worker.
constexpr std::size_t kThumbnailOnGuiThread = std::size_t(1) << 20;

// A map's thumbnail, `side` pixels at most (box-filtered, then fitted smoothly).
template <class Map> QImage thumbnail(const Map& map, int side) {
    const QImage image = toQImage(map, side);
    return image.isNull() ? image
                          : image.scaled(side, side, Qt::KeepAspectRatio, Qt::SmoothTransformation);
}

// Calls `f` with `kind`'s map in `a` (an Image, a HeightField or a ConeMap).
template <class F> auto withMap(const MaterialAssets& a, MapKind kind, F&& f) {
    switch (kind) {
    case MapKind::Albedo:
        return f(a.albedo);
    case MapKind::Height:
        return f(a.height);
    case MapKind::Normal:
        return f(a.normal);
    case MapKind::Cone:
        return f(a.cone);
    case MapKind::RelaxedCone:
        return f(a.relaxedCone);
    case MapKind::Ao:
        return f(a.ao);
    case MapKind::Roughness:
        return f(a.roughness);
    case MapKind::Metallic:
        return f(a.metallic);
    case MapKind::Specular:
        return f(a.specular);
    }
    return f(a.albedo); // not reached: every kind is named above
}

// The texels of a map, as a weak handle (SharedTexels::identity).
std::weak_ptr<const void> texelsOf(const Image& m) {
    return m.pixels.identity();
}
std::weak_ptr<const void> texelsOf(const HeightField& m) {
    return m.texels.identity();
}
std::weak_ptr<const void> texelsOf(const ConeMap& m) {
    return m.sqrtRatio.identity();
}

} // namespace

MapRow::MapRow(MapKind kind, bool bakeable, QWidget* parent) : QWidget(parent), m_kind(kind) {
    setAcceptDrops(true);
    setObjectName(QStringLiteral("map-%1").arg(QString::fromUtf8(mapKey(kind).data())));
    m_thumbnail = new QLabel(this);
    m_thumbnail->setObjectName(QStringLiteral("thumbnail"));
    m_thumbnail->setFixedSize(kThumbnail, kThumbnail);
    m_thumbnail->setFrameShape(QFrame::StyledPanel);
    m_title = new QLabel(QStringLiteral("<b>%1</b>").arg(mapTitle(kind).data()), this);
    m_source = new QLabel(this);
    m_source->setTextFormat(Qt::PlainText);
    m_source->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_source->setWordWrap(true); // "made here, not saved yet" wraps rather than being cut
    m_warning = new QLabel(this);
    m_warning->setTextFormat(Qt::PlainText);
    m_warning->setWordWrap(true);
    m_warning->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_warning->setStyleSheet(QStringLiteral("QLabel { color: #b35c00; }"));
    m_warning->hide();
    m_load = new QToolButton(this);
    m_load->setText(tr("Load…"));
    m_load->setToolTip(tr("Load the %1 map from a file (or drop a file on this row).")
                           .arg(QString::fromUtf8(mapTitle(kind).data()).toLower()));
    m_clear = new QToolButton(this);
    m_clear->setText(tr("Clear"));
    m_clear->setToolTip(tr("Remove this map from the material."));

    auto* text = new QVBoxLayout;
    text->setSpacing(0);
    text->addWidget(m_title);
    text->addWidget(m_source);
    text->addWidget(m_warning);
    auto* top = new QHBoxLayout;
    m_top = top;
    top->setContentsMargins(0, 0, 0, 0);
    top->addWidget(m_thumbnail);
    top->addLayout(text, 1);
    m_buttons = new QWidget(this);
    auto* buttons = new QHBoxLayout(m_buttons);
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->addStretch();
    m_arrangement = new QBoxLayout(QBoxLayout::LeftToRight, this);
    m_arrangement->setContentsMargins(2, 2, 2, 2);
    m_arrangement->addLayout(top, 1);
    m_arrangement->addWidget(m_buttons);
    QBoxLayout* layout = buttons;
    if (bakeable) {
        m_bake = new QToolButton(this);
        m_bake->setText(tr("Bake"));
        m_bake->setToolTip(
            kind == MapKind::Normal
                ? tr("Bake a normal map from the height map at the material's height scale.")
            : kind == MapKind::Cone
                ? tr("Bake a conservative cone map (no point of the bilinear surface inside any "
                     "cone) for cone step mapping.")
            : kind == MapKind::Ao
                ? tr("Bake the ambient occlusion of the height map at the material's height "
                     "scale, out to the occlusion distance (Baking, below).")
                : tr("Bake a relaxed cone map for relaxed cone stepping."));
        layout->addWidget(m_bake);
        connect(m_bake, &QToolButton::clicked, this, [this] { emit bakeRequested(m_kind); });
    }
    layout->addWidget(m_load);
    layout->addWidget(m_clear);
    connect(m_load, &QToolButton::clicked, this, [this] { emit loadRequested(m_kind); });
    connect(m_clear, &QToolButton::clicked, this, [this] { emit clearRequested(m_kind); });
}

void MapRow::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    arrange(event->size().width());
}

QSize MapRow::minimumSizeHint() const {
    // The buttons under the text: the panel may be as narrow as that (arrange() moves them).
    const QSize beside = QWidget::minimumSizeHint();
    const QMargins m = m_arrangement->contentsMargins();
    const int under = std::max(m_thumbnail->width() + 2 * m_arrangement->spacing(),
                               m_buttons->minimumSizeHint().width()) +
                      m.left() + m.right();
    return {std::min(beside.width(), under), beside.height()};
}

void MapRow::arrange(int width) {
    // Beside the text where the title and the buttons both fit, else under it.
    // The texts' own minimum counts too: a source or warning line may be wider than the title.
    const QMargins m = m_arrangement->contentsMargins();
    const int texts =
        std::max(m_thumbnail->width() + m_title->sizeHint().width() + 2 * m_arrangement->spacing(),
                 m_top->minimumSize().width());
    const int wide =
        texts + m_buttons->sizeHint().width() + m_arrangement->spacing() + m.left() + m.right() + 8;
    const auto direction = width >= wide ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom;
    if (m_arrangement->direction() != direction)
        m_arrangement->setDirection(direction);
}

QString MapRow::sourceText() const {
    return m_source->text();
}

void MapRow::setWarning(const QString& text) {
    m_warning->setText(text);
    m_warning->setToolTip(text);
    m_warning->setVisible(!text.isEmpty());
}

QString MapRow::warningText() const {
    return m_warning->text();
}

void MapRow::setBakeEnabled(bool enabled) {
    if (m_bake)
        m_bake->setEnabled(enabled);
}

void MapRow::refresh(const DocumentState& state) {
    const bool present = state.hasMap(m_kind);
    const std::string& path = mapPath(state.material.maps, m_kind);
    QString source;
    if (!present)
        source = tr("none");
    else if (state.isUnsaved(m_kind))
        source = tr("made here, not saved yet");
    else
        source = QFileInfo(QString::fromStdString(path)).fileName();
    if (const QString baked = m_kind == MapKind::Ao ? occlusionBakeSummary(state) : QString();
        !baked.isEmpty())
        source += QStringLiteral(" · ") + baked;
    if (present && m_kind == MapKind::Height) {
        const HeightField& h = state.assets->height;
        source += QStringLiteral(" · %1×%2").arg(h.width).arg(h.height);
    }
    m_source->setText(source);
    m_source->setToolTip(path.empty() ? source : QString::fromStdString(path));
    m_clear->setEnabled(present && m_kind != MapKind::Height);

    const double ratio = window() && window()->windowHandle()
                             ? window()->windowHandle()->devicePixelRatio()
                             : devicePixelRatioF();
    const int side = static_cast<int>(kThumbnail * ratio);
    const MaterialAssets& a = *state.assets;
    const std::weak_ptr<const void> texels =
        withMap(a, m_kind, [](const auto& map) { return texelsOf(map); });
    const std::owner_less<std::weak_ptr<const void>> before;
    if (side == m_shownSide && !before(texels, m_shownTexels) && !before(m_shownTexels, texels))
        return;
    m_shownTexels = texels;
    m_shownSide = side;
    ++m_thumbnailSerial;
    std::size_t texelCount = 0;
    const auto make = withMap(a, m_kind, [side, &texelCount](const auto& map) {
        texelCount = std::size_t(map.width) * std::size_t(map.height);
        // A copy shares the texels (SharedTexels): the job reads them on another thread.
        return std::function<QImage()>([map, side] { return thumbnail(map, side); });
    });
    if (texelCount <= kThumbnailOnGuiThread) {
        showThumbnail(make(), ratio);
        return;
    }
    // A box filter over 64 M texels took 37 ms of the GUI thread after a cone bake at 8192²
    // (perf, the studio memory benchmark): big maps' thumbnails are made beside it.
    auto* watcher = new QFutureWatcher<QImage>(this);
    connect(watcher, &QFutureWatcherBase::finished, this,
            [this, watcher, serial = m_thumbnailSerial, ratio] {
                watcher->deleteLater();
                if (serial == m_thumbnailSerial) // else a later map's thumbnail is on its way
                    showThumbnail(watcher->result(), ratio);
            });
    watcher->setFuture(QtConcurrent::run(make));
}

void MapRow::showThumbnail(const QImage& image, double ratio) {
    if (image.isNull()) {
        m_thumbnail->clear();
        return;
    }
    ++g_thumbnails;
    QPixmap pixmap = QPixmap::fromImage(image);
    pixmap.setDevicePixelRatio(ratio);
    m_thumbnail->setPixmap(pixmap);
}

int MapRow::thumbnailsMade() {
    return g_thumbnails;
}

void MapRow::dragEnterEvent(QDragEnterEvent* event) {
    const QMimeData* mime = event->mimeData();
    if (mime->hasUrls() && mime->urls().size() == 1 && mime->urls().front().isLocalFile())
        event->acceptProposedAction();
}

void MapRow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.front().isLocalFile()) {
        event->acceptProposedAction();
        emit fileDropped(m_kind, urls.front().toLocalFile());
    }
}

} // namespace px::studio

#include "preview/HeatLegend.h"

#include "preview/ErrorStats.h"

#include <QFontMetrics>
#include <QLinearGradient>
#include <QObject>
#include <QPainter>
#include <algorithm>
#include <span>

namespace px::studio {

namespace {

QString stopLabel(std::size_t i, std::size_t count, float texels) {
    const QString value = QString::number(texels, 'g', 3);
    return i + 1 == count ? QStringLiteral("≥") + value : value; // the top: that much or more
}

// The labels of the stops kept, centred under their stops and kept inside the bar's span; empty
// where two would come closer than `gap`.
std::vector<HeatLegendLayout::Label> placeLabels(const QFontMetrics& fm, QRect bar,
                                                 const std::vector<std::size_t>& kept, int gap) {
    const std::span<const HeatStop> stops = heatStops();
    const float top = stops.back().texels;
    std::vector<HeatLegendLayout::Label> labels;
    int right = bar.left() - gap; // the last label's right edge so far
    for (std::size_t i : kept) {
        const QString text = stopLabel(i, stops.size(), stops[i].texels);
        const int width = fm.horizontalAdvance(text);
        const int centre = bar.left() + static_cast<int>(bar.width() * stops[i].texels / top);
        const int left =
            std::clamp(centre - width / 2, bar.left(), bar.left() + bar.width() - width);
        if (left < right + gap)
            return {};
        labels.push_back({text, QRect(left, bar.bottom() + 3, width, fm.height())});
        right = left + width;
    }
    return labels;
}

} // namespace

HeatLegendLayout layoutHeatLegend(const QFontMetrics& fm, QSize view) {
    const int h = fm.height();
    const int margin = h / 2, pad = 4, gap = std::max(4, fm.horizontalAdvance(QLatin1Char(' ')));
    const QString unit = QObject::tr("texels");
    const int unitWidth = fm.horizontalAdvance(unit);
    const std::size_t count = heatStops().size();
    // Every stop, then without the middle ones, until the labels fit the view.
    std::vector<std::size_t> kept(count);
    for (std::size_t i = 0; i < count; ++i)
        kept[i] = i;
    HeatLegendLayout layout;
    for (;;) {
        const int room = view.width() - 2 * margin - 2 * pad - gap - unitWidth;
        // The narrowest bar (8 font heights where there is room) that keeps the labels apart.
        for (int width = std::max(2 * h, std::min(8 * h, room));; width += std::max(1, h / 4)) {
            const QRect bar(margin + pad, view.height() - margin - pad - h - 3 - h / 2, width,
                            h / 2);
            std::vector<HeatLegendLayout::Label> labels = placeLabels(fm, bar, kept, gap);
            if (!labels.empty() || width > room) {
                layout.bar = bar;
                layout.labels = std::move(labels);
                break;
            }
        }
        if (!layout.labels.empty() && layout.bar.width() <= room)
            break;
        if (kept.size() <= 2) { // only the ends: shown even in a view too narrow for them
            layout.labels = placeLabels(fm, layout.bar, kept, 0);
            break;
        }
        kept.erase(kept.begin() + 1); // 0.5, then 1
    }
    const QRect unitRect(layout.bar.right() + 1 + gap, layout.bar.center().y() - h / 2, unitWidth,
                         h);
    layout.labels.push_back({unit, unitRect});
    QRect all = layout.bar;
    for (const HeatLegendLayout::Label& label : layout.labels)
        all = all.united(label.rect);
    layout.backdrop = all.adjusted(-pad, -pad, pad, pad);
    return layout;
}

void drawHeatLegend(QPainter& painter, const HeatLegendLayout& layout) {
    const std::span<const HeatStop> stops = heatStops();
    QLinearGradient gradient(layout.bar.topLeft(), layout.bar.topRight());
    for (const HeatStop& stop : stops)
        gradient.setColorAt(stop.texels / stops.back().texels, stop.colour);
    painter.fillRect(layout.backdrop, QColor(0, 0, 0, 150));
    painter.fillRect(layout.bar, gradient);
    painter.setPen(Qt::white);
    for (const HeatLegendLayout::Label& label : layout.labels)
        painter.drawText(label.rect, Qt::AlignLeft | Qt::AlignVCenter, label.text);
}

} // namespace px::studio

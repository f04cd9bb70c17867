#pragma once
// The heat map's scale in a view's bottom-left corner: the colour bar as heatMapImage colours the
// error (ErrorStats.h), a label under each stop and the unit after the bar. Laid out from the
// view's font, so no two labels overlap at any font size or scale; where the view is too narrow
// for every label the middle ones are left out (0 and the top of the scale stay).

#include <QRect>
#include <QString>
#include <vector>

class QFontMetrics;
class QPainter;

namespace px::studio {

struct HeatLegendLayout {
    struct Label {
        QString text;
        QRect rect;
    };
    QRect backdrop;            // the dark panel behind it, inside the view
    QRect bar;                 // the gradient
    std::vector<Label> labels; // the stops' values, left to right, then the unit
};

HeatLegendLayout layoutHeatLegend(const QFontMetrics& metrics, QSize view);
void drawHeatLegend(QPainter& painter, const HeatLegendLayout& layout);

} // namespace px::studio

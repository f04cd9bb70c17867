#include "panels/WorkPrecisionView.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <cmath>

namespace px::studio {

WorkPrecisionView::WorkPrecisionView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setStatusTip(tr("Lower is more accurate, left is cheaper: the dashed line is the Pareto front. "
                    "Click a point to use that technique and setting in the active viewport."));
    m_placeholder = tr("Run the comparison (Ctrl+R) to measure every technique's error against "
                       "its cost on this material.");
}

void WorkPrecisionView::setPlaceholderText(const QString& text) {
    m_placeholder = text;
    update();
}

QColor WorkPrecisionView::techniqueColour(Technique technique) {
    switch (technique) {
    case Technique::Offset:
        return QColor(150, 150, 150);
    case Technique::Steep:
        return QColor(31, 119, 180);
    case Technique::Pom:
        return QColor(255, 127, 14);
    case Technique::Relief:
        return QColor(44, 160, 44);
    case Technique::Secant:
        return QColor(214, 39, 40);
    case Technique::Cone:
        return QColor(148, 103, 189);
    case Technique::RelaxedCone:
        return QColor(140, 86, 75);
    case Technique::Pyramid:
        return QColor(227, 119, 194);
    case Technique::Exact:
        return QColor(23, 190, 207);
    default:
        return QColor(90, 90, 90);
    }
}

void WorkPrecisionView::setPanel(const WorkPrecisionPanel& panel) {
    m_panel = panel;
    m_hover.reset();
    m_highlight.reset();
    update();
}

void WorkPrecisionView::clear() {
    m_panel.reset();
    m_hover.reset();
    m_highlight.reset();
    update();
}

void WorkPrecisionView::setHighlight(std::optional<PointRef> ref) {
    m_highlight = ref;
    update();
}

QRectF WorkPrecisionView::plotRect() const {
    const QFontMetricsF fm(font());
    const double left = fm.horizontalAdvance(QStringLiteral("10⁻⁰⁰")) + fm.height() * 1.6;
    const double bottom = fm.height() * 2.8;
    const double legend = fm.horizontalAdvance(QStringLiteral("relaxed-cone")) + fm.height() * 2.5;
    return QRectF(left, fm.height(), width() - left - legend, height() - fm.height() - bottom);
}

QPointF WorkPrecisionView::toWidget(double cost, double error) const {
    const QRectF r = plotRect();
    const LogRange& c = m_panel->costRange;
    const LogRange& e = m_panel->errorRange;
    const double x = (std::log10(cost) - c.loExp) / double(c.hiExp - c.loExp);
    const double y = (std::log10(error) - e.loExp) / double(e.hiExp - e.loExp);
    return {r.left() + x * r.width(), r.bottom() - y * r.height()};
}

QPointF WorkPrecisionView::pointPosition(PointRef ref) const {
    const WorkPrecisionPoint& p = m_panel->at(ref);
    return toWidget(p.cost, p.plotError);
}

std::optional<PointRef> WorkPrecisionView::pointAt(QPointF position) const {
    if (!m_panel)
        return std::nullopt;
    // Nearest drawn point within a few font heights (HiDPI: in logical pixels).
    const double reach = QFontMetricsF(font()).height() * 0.8;
    std::optional<PointRef> best;
    double bestDistance = reach;
    for (std::size_t s = 0; s < m_panel->series.size(); ++s) {
        for (std::size_t i = 0; i < m_panel->series[s].points.size(); ++i) {
            const QPointF d = pointPosition({s, i}) - position;
            const double distance = std::hypot(d.x(), d.y());
            if (distance <= bestDistance) {
                bestDistance = distance;
                best = PointRef{s, i};
            }
        }
    }
    return best;
}

namespace {
QString decade(int exponent) {
    static const QString superscripts = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    QString digits;
    for (QChar c : QString::number(std::abs(exponent)))
        digits += superscripts[c.digitValue()];
    return QStringLiteral("10") + (exponent < 0 ? QStringLiteral("⁻") : QString()) + digits;
}
} // namespace

void WorkPrecisionView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().color(QPalette::Base));
    const QPalette& pal = palette();
    if (!m_panel || m_panel->series.empty()) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap,
                   m_placeholder);
        return;
    }
    const QRectF r = plotRect();
    const QFontMetricsF fm(font());
    const LogRange& c = m_panel->costRange;
    const LogRange& e = m_panel->errorRange;

    // Grid and decade labels.
    p.setPen(QPen(pal.color(QPalette::Midlight), 1));
    for (int k = c.loExp; k <= c.hiExp; ++k) {
        const double x = toWidget(std::pow(10.0, k), std::pow(10.0, e.loExp)).x();
        p.setPen(QPen(pal.color(QPalette::Midlight), 1));
        p.drawLine(QPointF(x, r.top()), QPointF(x, r.bottom()));
        p.setPen(pal.color(QPalette::Text));
        p.drawText(QRectF(x - 40, r.bottom() + 2, 80, fm.height()), Qt::AlignHCenter, decade(k));
    }
    for (int k = e.loExp; k <= e.hiExp; ++k) {
        const double y = toWidget(std::pow(10.0, c.loExp), std::pow(10.0, k)).y();
        p.setPen(QPen(pal.color(QPalette::Midlight), 1));
        p.drawLine(QPointF(r.left(), y), QPointF(r.right(), y));
        p.setPen(pal.color(QPalette::Text));
        p.drawText(QRectF(0, y - fm.height() / 2, r.left() - 4, fm.height()), Qt::AlignRight,
                   decade(k));
    }
    p.setPen(QPen(pal.color(QPalette::Text), 1));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    p.drawText(QRectF(r.left(), r.bottom() + fm.height() * 1.3, r.width(), fm.height()),
               Qt::AlignHCenter, QString::fromUtf8(costAxisTitle(m_panel->axis).data()));
    p.save();
    p.translate(fm.height() * 0.2, r.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-r.height() / 2, 0, r.height(), fm.height()), Qt::AlignHCenter,
               tr("p99 error (texels) at %1°").arg(m_panel->polarDeg));
    p.restore();

    // The Pareto front under the curves.
    if (m_panel->front.size() > 1) {
        QPainterPath front;
        for (std::size_t i = 0; i < m_panel->front.size(); ++i) {
            const QPointF q = pointPosition(m_panel->front[i]);
            i == 0 ? front.moveTo(q) : front.lineTo(q);
        }
        p.setPen(QPen(pal.color(QPalette::Text), 1.5, Qt::DashLine));
        p.drawPath(front);
    }

    const double radius = fm.height() * 0.22;
    double legendY = r.top();
    for (std::size_t s = 0; s < m_panel->series.size(); ++s) {
        const WorkPrecisionSeries& series = m_panel->series[s];
        const QColor colour = techniqueColour(series.technique);
        QPainterPath curve;
        for (std::size_t i = 0; i < series.points.size(); ++i) {
            const QPointF q = pointPosition({s, i});
            i == 0 ? curve.moveTo(q) : curve.lineTo(q);
        }
        p.setPen(QPen(colour, 2));
        p.setBrush(Qt::NoBrush);
        p.drawPath(curve);
        for (std::size_t i = 0; i < series.points.size(); ++i) {
            const WorkPrecisionPoint& point = series.points[i];
            const bool hover = m_hover && m_hover->series == s && m_hover->point == i;
            p.setPen(
                QPen(point.onFront ? pal.color(QPalette::Text) : colour, point.onFront ? 1.5 : 1));
            p.setBrush(point.setting.isDefault ? pal.color(QPalette::Base) : colour);
            p.drawEllipse(pointPosition({s, i}), hover ? radius * 2 : radius * 1.3,
                          hover ? radius * 2 : radius * 1.3);
            if (m_highlight && m_highlight->series == s && m_highlight->point == i) {
                p.setPen(QPen(pal.color(QPalette::Highlight), 2.5));
                p.setBrush(Qt::NoBrush);
                p.drawEllipse(pointPosition({s, i}), radius * 3, radius * 3);
            }
        }
        // Legend.
        const double lx = r.right() + fm.height();
        p.setPen(QPen(colour, 3));
        p.drawLine(QPointF(lx, legendY + fm.height() / 2),
                   QPointF(lx + fm.height(), legendY + fm.height() / 2));
        p.setPen(pal.color(QPalette::Text));
        p.drawText(QPointF(lx + fm.height() * 1.3, legendY + fm.ascent()),
                   QString::fromUtf8(info(series.technique).name.data()));
        legendY += fm.height() * 1.2;
    }
}

void WorkPrecisionView::mouseMoveEvent(QMouseEvent* event) {
    const std::optional<PointRef> hover = pointAt(event->position());
    if (hover.has_value() != m_hover.has_value() ||
        (hover && (hover->series != m_hover->series || hover->point != m_hover->point))) {
        m_hover = hover;
        update();
    }
    if (!hover) {
        QToolTip::hideText();
        return;
    }
    const WorkPrecisionPoint& p = m_panel->at(*hover);
    const QString label = QString::fromStdString(p.setting.label);
    QToolTip::showText(
        event->globalPosition().toPoint(),
        tr("<b>%1</b> %2<br>p99 error %3 texels<br>%4: %5<br><i>Click to use it in the active "
           "viewport.</i>")
            .arg(QString::fromUtf8(info(p.setting.technique).name.data()),
                 label.isEmpty() ? QString() : QStringLiteral("(%1)").arg(label))
            .arg(p.error, 0, 'g', 3)
            .arg(QString::fromUtf8(costAxisTitle(m_panel->axis).data()))
            .arg(p.cost, 0, 'g', 4),
        this);
}

void WorkPrecisionView::mousePressEvent(QMouseEvent* event) {
    if (const std::optional<PointRef> hit = pointAt(event->position()))
        emit pointClicked(m_panel->at(*hit));
}

void WorkPrecisionView::leaveEvent(QEvent*) {
    m_hover.reset();
    update();
}

} // namespace px::studio

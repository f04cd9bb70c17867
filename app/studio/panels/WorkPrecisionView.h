#pragma once
// The work-precision diagram of one panel (one polar angle, one cost axis): p99 error against
// cost on log-log axes, one curve per technique across its settings, the Pareto front dashed.
// Hovering a point says what it is; clicking it picks it.

#include "parallax/eval/WorkPrecision.h"

#include <QWidget>
#include <optional>

namespace px::studio {

class WorkPrecisionView : public QWidget {
    Q_OBJECT
public:
    explicit WorkPrecisionView(QWidget* parent = nullptr);

    void setPanel(const WorkPrecisionPanel& panel);
    void clear();
    // What the view says while it has no panel (what to do, or that a run is under way).
    void setPlaceholderText(const QString& text);
    QString placeholderText() const { return m_placeholder; }
    // A point drawn ringed (the editor's Auto choice); reset by setPanel and clear.
    void setHighlight(std::optional<PointRef> ref);
    std::optional<PointRef> highlight() const { return m_highlight; }
    bool hasPanel() const { return m_panel.has_value(); }
    const WorkPrecisionPanel& panel() const { return *m_panel; }
    // Where a point is drawn, in widget coordinates (tests click there).
    QPointF pointPosition(PointRef ref) const;

    QSize sizeHint() const override { return {520, 320}; }
    QSize minimumSizeHint() const override { return {240, 160}; }

    static QColor techniqueColour(Technique technique);

signals:
    void pointClicked(const px::WorkPrecisionPoint& point);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    QRectF plotRect() const;
    QPointF toWidget(double cost, double error) const;
    std::optional<PointRef> pointAt(QPointF position) const;

    std::optional<WorkPrecisionPanel> m_panel;
    QString m_placeholder;
    std::optional<PointRef> m_hover;
    std::optional<PointRef> m_highlight;
};

} // namespace px::studio

#pragma once
// A slider with two handles for a range [low, high] within [0, 1]: the tutorial shaders' two-value
// quality range. Drag a handle (or the bar between them); arrow keys move the low handle,
// Shift+arrows the high one.

#include <QWidget>

namespace px::studio {

class RangeSlider : public QWidget {
    Q_OBJECT
public:
    explicit RangeSlider(QWidget* parent = nullptr);

    double low() const { return m_low; }
    double high() const { return m_high; }
    // Shows a range without emitting rangeEdited.
    void setRange(double low, double high);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void rangeEdited(double low, double high);
    void editFinished();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    enum class Grab { None, Low, High, Both };
    double valueAt(double x) const;
    double xOf(double value) const;
    void move(double low, double high);

    double m_low = 0.2;
    double m_high = 0.6;
    Grab m_grab = Grab::None;
    double m_grabOffset = 0.0;
};

} // namespace px::studio

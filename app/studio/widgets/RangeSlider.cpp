#include "widgets/RangeSlider.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QStyle>
#include <algorithm>
#include <cmath>

namespace px::studio {

namespace {
double handleRadius(const QWidget* w) {
    return std::max(5.0, w->fontMetrics().height() * 0.4);
}
} // namespace

RangeSlider::RangeSlider(QWidget* parent) : QWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

QSize RangeSlider::sizeHint() const {
    return {fontMetrics().horizontalAdvance(QStringLiteral("0")) * 16,
            static_cast<int>(std::ceil(handleRadius(this) * 2 + 4))};
}

QSize RangeSlider::minimumSizeHint() const {
    return {fontMetrics().horizontalAdvance(QStringLiteral("0")) * 6, sizeHint().height()};
}

void RangeSlider::setRange(double low, double high) {
    m_low = std::clamp(low, 0.0, 1.0);
    m_high = std::clamp(high, m_low, 1.0);
    update();
}

double RangeSlider::xOf(double value) const {
    const double r = handleRadius(this);
    return r + value * (width() - 2 * r);
}

double RangeSlider::valueAt(double x) const {
    const double r = handleRadius(this);
    return std::clamp((x - r) / std::max(1.0, width() - 2 * r), 0.0, 1.0);
}

void RangeSlider::move(double low, double high) {
    low = std::clamp(low, 0.0, 1.0);
    high = std::clamp(high, 0.0, 1.0);
    if (low > high)
        std::swap(low, high);
    if (low == m_low && high == m_high)
        return;
    m_low = low;
    m_high = high;
    update();
    emit rangeEdited(m_low, m_high);
}

void RangeSlider::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double r = handleRadius(this);
    const double cy = height() / 2.0;
    const QPalette& pal = palette();
    p.setPen(Qt::NoPen);
    p.setBrush(pal.color(QPalette::Mid));
    p.drawRoundedRect(QRectF(r, cy - 2, width() - 2 * r, 4), 2, 2);
    p.setBrush(pal.color(isEnabled() ? QPalette::Highlight : QPalette::Mid));
    p.drawRect(QRectF(xOf(m_low), cy - 2, xOf(m_high) - xOf(m_low), 4));
    p.setPen(QPen(pal.color(QPalette::Dark), 1));
    p.setBrush(pal.color(QPalette::Button));
    for (double v : {m_low, m_high})
        p.drawEllipse(QPointF(xOf(v), cy), r - 1, r - 1);
    if (hasFocus()) {
        p.setPen(QPen(pal.color(QPalette::Highlight), 1, Qt::DotLine));
        p.setBrush(Qt::NoBrush);
        p.drawRect(rect().adjusted(0, 0, -1, -1));
    }
}

void RangeSlider::mousePressEvent(QMouseEvent* event) {
    const double x = event->position().x();
    const double r = handleRadius(this);
    const double dLow = std::abs(x - xOf(m_low)), dHigh = std::abs(x - xOf(m_high));
    if (dLow <= r || dHigh <= r)
        m_grab = dLow < dHigh || (dLow == dHigh && x < xOf(m_low)) ? Grab::Low : Grab::High;
    else if (x > xOf(m_low) && x < xOf(m_high))
        m_grab = Grab::Both;
    else
        m_grab = x < xOf(m_low) ? Grab::Low : Grab::High;
    m_grabOffset = valueAt(x) - m_low;
    mouseMoveEvent(event);
}

void RangeSlider::mouseMoveEvent(QMouseEvent* event) {
    const double v = valueAt(event->position().x());
    switch (m_grab) {
    case Grab::Low:
        move(std::min(v, m_high), m_high);
        break;
    case Grab::High:
        move(m_low, std::max(v, m_low));
        break;
    case Grab::Both: {
        const double width = m_high - m_low;
        const double low = std::clamp(v - m_grabOffset, 0.0, 1.0 - width);
        move(low, low + width);
        break;
    }
    case Grab::None:
        break;
    }
}

void RangeSlider::mouseReleaseEvent(QMouseEvent*) {
    if (m_grab != Grab::None)
        emit editFinished();
    m_grab = Grab::None;
}

void RangeSlider::keyPressEvent(QKeyEvent* event) {
    const double step = event->modifiers() & Qt::ControlModifier ? 0.1 : 0.02;
    double delta = 0;
    if (event->key() == Qt::Key_Left || event->key() == Qt::Key_Down)
        delta = -step;
    else if (event->key() == Qt::Key_Right || event->key() == Qt::Key_Up)
        delta = step;
    else
        return QWidget::keyPressEvent(event);
    if (event->modifiers() & Qt::ShiftModifier)
        move(m_low, std::max(m_low, m_high + delta));
    else
        move(std::min(m_high, m_low + delta), m_high);
    emit editFinished();
}

} // namespace px::studio

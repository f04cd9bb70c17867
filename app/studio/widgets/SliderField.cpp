#include "widgets/SliderField.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <algorithm>
#include <cmath>

namespace px::studio {

namespace {
constexpr int kSliderSteps = 1000; // decimal sliders: this many positions across their range
}

SliderField::SliderField(const QString& label, const Range& range, QWidget* parent)
    : QWidget(parent), m_range(range) {
    m_label = new QLabel(label, this);
    m_slider = new QSlider(Qt::Horizontal, this);
    m_field = new QDoubleSpinBox(this);
    m_label->setBuddy(m_field);

    const bool integer = range.decimals == 0;
    m_slider->setRange(integer ? static_cast<int>(range.sliderMin) : 0,
                       integer ? static_cast<int>(range.sliderMax) : kSliderSteps);
    m_slider->setSingleStep(1);
    m_slider->setPageStep(integer ? std::max(1, (m_slider->maximum() - m_slider->minimum()) / 8)
                                  : kSliderSteps / 10);
    m_field->setRange(range.fieldMin, range.fieldMax);
    m_field->setDecimals(range.decimals);
    m_field->setSingleStep(range.step);
    m_field->setKeyboardTracking(false); // typing "0.1" must not apply 0 then 0.1
    m_field->setAccelerated(true);
    m_field->setMinimumWidth(m_field->fontMetrics().horizontalAdvance(QStringLiteral("00000.000")));
    m_field->setAlignment(Qt::AlignRight);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_label, 3);
    layout->addWidget(m_slider, 5);
    layout->addWidget(m_field, 2);

    connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
        const double v = fromSlider(position);
        {
            const QSignalBlocker block(m_field);
            m_field->setValue(v);
        }
        emit valueEdited(m_field->value());
        if (!m_slider->isSliderDown()) // a key press or page step: one undo step each
            emit editFinished();
    });
    connect(m_slider, &QSlider::sliderReleased, this, &SliderField::editFinished);
    connect(m_field, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        {
            const QSignalBlocker block(m_slider);
            m_slider->setValue(toSlider(v));
        }
        emit valueEdited(v);
        // A typed or stepped value is a step of its own, not part of a drag.
        if (!m_slider->isSliderDown())
            emit editFinished();
    });
}

double SliderField::value() const {
    return m_field->value();
}

void SliderField::setValue(double value) {
    const QSignalBlocker blockField(m_field);
    const QSignalBlocker blockSlider(m_slider);
    m_field->setValue(value);
    m_slider->setValue(toSlider(value));
}

void SliderField::setSuffix(const QString& suffix) {
    m_field->setSuffix(suffix);
}

void SliderField::setHint(const QString& hint) {
    for (QWidget* w : {static_cast<QWidget*>(m_label), static_cast<QWidget*>(m_slider),
                       static_cast<QWidget*>(m_field)}) {
        w->setToolTip(hint);
        w->setStatusTip(hint);
    }
}

int SliderField::toSlider(double value) const {
    if (m_range.decimals == 0)
        return static_cast<int>(std::lround(value));
    const double t = (value - m_range.sliderMin) / (m_range.sliderMax - m_range.sliderMin);
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps));
}

double SliderField::fromSlider(int position) const {
    if (m_range.decimals == 0)
        return position;
    return m_range.sliderMin + (m_range.sliderMax - m_range.sliderMin) * position / kSliderSteps;
}

} // namespace px::studio

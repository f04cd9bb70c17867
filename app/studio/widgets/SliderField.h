#pragma once
// A labelled slider with a numeric field beside it: the slider for dragging through the useful
// range, the field for typing any valid value (a value beyond the slider's range is kept as typed,
// never clamped to it). Integers or decimals.

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace px::studio {

class SliderField : public QWidget {
    Q_OBJECT
public:
    struct Range {
        double sliderMin, sliderMax; // what the slider spans
        double fieldMin, fieldMax;   // what the field accepts
        int decimals;                // 0: integers
        double step;                 // arrow keys and wheel
    };

    SliderField(const QString& label, const Range& range, QWidget* parent = nullptr);

    double value() const;
    // Shows a value without emitting valueEdited (the document changed, not the user).
    void setValue(double value);
    void setSuffix(const QString& suffix);
    // The tooltip and status-bar hint of the label, slider and field.
    void setHint(const QString& hint);

    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* field() const { return m_field; }

signals:
    void valueEdited(double value); // the user moved the slider or typed a value
    void editFinished();            // the drag ended or the typing was committed

private:
    int toSlider(double value) const;
    double fromSlider(int position) const;

    Range m_range;
    QLabel* m_label;
    QSlider* m_slider;
    QDoubleSpinBox* m_field;
};

} // namespace px::studio

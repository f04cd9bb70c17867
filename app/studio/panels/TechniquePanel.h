#pragma once
// The technique and quality of the active viewport (viewport 1's are the material's): layers,
// the tutorial shaders' quality range, refinement steps and the step cap, each shown only where the
// technique reads it.

#include "parallax/trace/Technique.h"

#include <QWidget>
#include <functional>

class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;

namespace px::studio {

class MaterialDocument;
class RangeSlider;
class SliderField;
class TechniqueCombo;
class WorkPrecisionView;
struct ViewQuality;

class TechniquePanel : public QWidget {
    Q_OBJECT
public:
    explicit TechniquePanel(MaterialDocument* document, QWidget* parent = nullptr);

    int viewport() const { return m_viewport; }
    void setViewport(int index); // 0-based

    TechniqueCombo* techniqueCombo() const { return m_technique; }
    SliderField* minLayers() const { return m_minLayers; }
    SliderField* maxLayers() const { return m_maxLayers; }
    RangeSlider* qualityRange() const { return m_quality; }
    SliderField* binarySteps() const { return m_binary; }
    SliderField* secantSteps() const { return m_secant; }
    SliderField* stepCap() const { return m_cap; }
    QDoubleSpinBox* autoBudget() const { return m_autoBudget; }
    QDoubleSpinBox* autoMaxPolar() const { return m_autoPolar; }
    QPushButton* autoPick() const { return m_autoPick; }
    QString autoStatus() const;
    // The last Pick's measured settings at the steepest angle, the choice ringed (hidden until
    // a Pick, and once the technique is chosen by hand).
    WorkPrecisionView* autoChart() const { return m_autoChart; }

private:
    void refresh();
    void editQuality(const QString& text, const QString& key,
                     const std::function<void(ViewQuality&)>& change);
    void setQualityRange(double low, double high);
    void pickAuto();

    MaterialDocument* m_document;
    int m_viewport = 0;
    QGroupBox* m_box;
    TechniqueCombo* m_technique;
    SliderField* m_minLayers;
    SliderField* m_maxLayers;
    QWidget* m_qualityRow;
    RangeSlider* m_quality;
    QDoubleSpinBox* m_qualityLow;
    QDoubleSpinBox* m_qualityHigh;
    SliderField* m_binary;
    SliderField* m_secant;
    SliderField* m_cap;
    QPushButton* m_defaults;
    QPushButton* m_useForMaterial;
    QGroupBox* m_autoBox;
    QDoubleSpinBox* m_autoBudget;
    QDoubleSpinBox* m_autoPolar;
    QPushButton* m_autoPick;
    QLabel* m_autoStatus;
    WorkPrecisionView* m_autoChart;
    QString m_autoNote; // the last resolution's note, while the material is still auto
};

// The tutorial shaders' quality (numSteps = clamp(quality * 50, 1, 50)) and layers.
int layersForQuality(double quality);
double qualityForLayers(int layers);

} // namespace px::studio

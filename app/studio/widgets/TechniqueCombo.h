#pragma once
// A technique chooser: every technique by its title, those whose maps are missing greyed out
// with the reason (a cone technique before a cone map is baked or loaded).

#include "parallax/trace/Technique.h"

#include <QComboBox>

namespace px::studio {

struct DocumentState;

class TechniqueCombo : public QComboBox {
    Q_OBJECT
public:
    explicit TechniqueCombo(QWidget* parent = nullptr);

    Technique technique() const;
    // Shows a technique without emitting techniqueChosen.
    void setTechnique(Technique technique);
    // Enables the techniques the state has the maps for.
    void updateAvailability(const DocumentState& state);
    bool isAvailable(Technique technique) const;

signals:
    void techniqueChosen(px::Technique technique);
};

} // namespace px::studio

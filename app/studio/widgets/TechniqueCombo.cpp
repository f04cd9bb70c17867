#include "widgets/TechniqueCombo.h"

#include "model/DocumentState.h"
#include "widgets/Hints.h"

#include <QSignalBlocker>
#include <QStandardItemModel>

namespace px::studio {

TechniqueCombo::TechniqueCombo(QWidget* parent) : QComboBox(parent) {
    for (const TechniqueInfo& t : allTechniques()) {
        addItem(QString::fromUtf8(t.name.data(), static_cast<int>(t.name.size())),
                static_cast<int>(t.id));
        setItemData(count() - 1, hints::technique(t.id), Qt::ToolTipRole);
    }
    setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(this, &QComboBox::activated, this, [this](int index) {
        emit techniqueChosen(static_cast<Technique>(itemData(index).toInt()));
    });
}

Technique TechniqueCombo::technique() const {
    return static_cast<Technique>(currentData().toInt());
}

void TechniqueCombo::setTechnique(Technique technique) {
    const QSignalBlocker block(this);
    setCurrentIndex(findData(static_cast<int>(technique)));
    setToolTip(hints::technique(technique));
}

bool TechniqueCombo::isAvailable(Technique technique) const {
    const auto* m = qobject_cast<const QStandardItemModel*>(model());
    const QStandardItem* item = m ? m->item(findData(static_cast<int>(technique))) : nullptr;
    return item && item->isEnabled();
}

void TechniqueCombo::updateAvailability(const DocumentState& state) {
    auto* m = qobject_cast<QStandardItemModel*>(model());
    if (!m)
        return;
    for (int i = 0; i < count(); ++i) {
        const auto t = static_cast<Technique>(itemData(i).toInt());
        const bool ok = state.canTrace(t);
        m->item(i)->setEnabled(ok);
        QString tip = hints::technique(t);
        if (!ok) {
            const TechniqueInfo& ti = info(t);
            tip = !state.hasMap(MapKind::Height) ? tr("Needs a height map.")
                  : ti.needsConeMap              ? tr("Needs a cone map: bake or load one.")
                                    : tr("Needs a relaxed cone map: bake or load one.");
        }
        m->item(i)->setToolTip(tip);
    }
}

} // namespace px::studio

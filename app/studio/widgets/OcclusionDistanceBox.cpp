#include "widgets/OcclusionDistanceBox.h"

#include <QDoubleSpinBox>
#include <cmath>

namespace px::studio {

QDoubleSpinBox* makeOcclusionDistanceBox(QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(QStringLiteral("occlusion-distance"));
    box->setRange(0.0, 100.0);
    box->setMinimumWidth(0); // the panel decides the width (it may be narrow)
    box->setDecimals(3);
    box->setSingleStep(0.01);
    box->setSuffix(QObject::tr(" uv"));
    box->setSpecialValueText(QObject::tr("unlimited")); // shown at 0, the minimum
    box->setValue(0.0);
    box->setToolTip(QObject::tr("How far a blocker may be from the point it darkens, in uv units "
                                "(1 = the tile's width). Unlimited: the whole tiled surface, as "
                                "the sky lights it; smaller values keep the occlusion local."));
    return box;
}

double occlusionDistanceOf(const QDoubleSpinBox* box) {
    return box->value() > 0.0 ? box->value() : INFINITY;
}

} // namespace px::studio

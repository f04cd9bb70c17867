#pragma once
// The occlusion bakes' distance D (docs/conventions.md §7): a spin box in uv units whose lowest
// value reads "unlimited" (the sky as the environment light sees it).

class QDoubleSpinBox;
class QWidget;

namespace px::studio {

QDoubleSpinBox* makeOcclusionDistanceBox(QWidget* parent);
// The box's distance: +inf for "unlimited".
double occlusionDistanceOf(const QDoubleSpinBox* box);

} // namespace px::studio

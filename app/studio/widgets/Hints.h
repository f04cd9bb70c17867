#pragma once
// What each control does, in the terms of the tutorial shaders (height_scale, numLayers,
// u_parallax_quality, ...): one place for the tooltips and status-bar hints, so the same control
// says the same thing in every panel.

#include "parallax/trace/Technique.h"

#include <QString>

namespace px::studio::hints {

QString heightScale();
QString depthMap();
QString heightChannel();
QString tiling();
QString wrap();
QString minLayers();
QString maxLayers();
QString qualityRange();
QString binarySteps();
QString secantSteps();
QString stepCap(Technique technique);
QString selfShadow();
QString shadowSoftness();
QString normalSource();
QString normalGreen();
QString lighting();
QString lightAzimuth();
QString lightElevation();
QString mesh();
QString loadMesh();
QString environment();
QString linkViews();
QString heatMap();
QString wipe();
QString technique(Technique technique);
QString viewportHelp();

} // namespace px::studio::hints

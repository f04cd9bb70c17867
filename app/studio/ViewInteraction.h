#pragma once
// What mouse gestures in a viewport do: drag orbits the camera, the wheel zooms, Ctrl+drag moves
// the light (azimuth with horizontal motion, elevation with vertical). Pure functions, so the
// gestures are tested without a window.

#include "ViewSettings.h"

#include <QPointF>

namespace px::studio {

// Degrees per logical pixel of drag: half a turn across a 720-pixel drag.
inline constexpr float kDegreesPerPixel = 0.25f;

OrbitCamera orbit(const OrbitCamera& camera, QPointF deltaPixels);
// `steps` wheel notches (120 units each); positive zooms in.
OrbitCamera zoom(const OrbitCamera& camera, double steps);
DirectionalLight moveLight(const DirectionalLight& light, QPointF deltaPixels);

inline constexpr float kMinDistance = 1.2f;
inline constexpr float kMaxDistance = 12.0f;

} // namespace px::studio

#pragma once
// What mouse gestures in a viewport do: drag orbits the camera, the wheel zooms, Ctrl+drag moves
// the light (azimuth with horizontal motion, elevation with vertical). Pure functions, so the
// gestures are tested without a window.

#include "preview/ViewSettings.h"

#include <QPointF>

namespace px::studio {

// Degrees per logical pixel of drag: half a turn across a 720-pixel drag.
inline constexpr float kDegreesPerPixel = 0.25f;

// The camera's elevation stays in [kMinElevation, kMaxElevation]: always above the material's
// surface (below it every view would show nothing), short of the pole where up would flip.
inline constexpr float kMinElevation = 1.0f;
inline constexpr float kMaxElevation = 89.0f;

OrbitCamera orbit(const OrbitCamera& camera, QPointF deltaPixels);
// The camera at a polar angle from the surface normal (90° - elevation), kept in range.
OrbitCamera withPolarAngle(const OrbitCamera& camera, double polarDeg);
// `steps` wheel notches (120 units each); positive zooms in.
OrbitCamera zoom(const OrbitCamera& camera, double steps);
DirectionalLight moveLight(const DirectionalLight& light, QPointF deltaPixels);

inline constexpr float kMinDistance = 1.2f;
inline constexpr float kMaxDistance = 12.0f;

} // namespace px::studio

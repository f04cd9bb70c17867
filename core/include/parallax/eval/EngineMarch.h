#pragma once
// The engines' own parallax marches, modelled so their layer counts can be measured and chosen
// like any technique's quality. An engine export cannot ship this project's kernels into the
// engine's standard material; it ships layer counts, and these models say which ones suffice.
//
// Godot 4 (BaseMaterial3D with heightmap_deep_parallax, scene/resources/material.cpp):
//   num_layers = mix(max_layers, min_layers, |view.z|)        a float, not rounded
//   P = view.xy * heightmap_scale * 0.01                       the normalised view vector
//   march ofs by P / num_layers while the layer depth < 1 - h(ofs), then interpolate linearly
//   between the last two samples.
// Because P comes from the normalised view vector, Godot offsets by s sin(polar) where the relief
// of height scale s needs s tan(polar): Godot's picture is flatter than the relief at grazing
// angles whatever the layers. Layers only decide how well Godot's march finds *its own* surface,
// so the layer count is judged against the exact hit of Godot's ray (RayModel::NormalisedView).

#include "parallax/Result.h"
#include "parallax/eval/EvalControl.h"
#include "parallax/eval/Recommendation.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/trace/Tracer.h"

#include <glm/vec2.hpp>
#include <string>
#include <vector>

namespace px {

struct EngineLayers {
    int minLayers = 8; // Godot's defaults
    int maxLayers = 32;
};

// Godot's layer count at a view angle: mix(max, min, |cos polar|), unrounded.
float godotLayerCount(const EngineLayers& layers, float cosPolar);

// One ray of Godot's deep parallax. P is Godot's offset at full depth in uv units (s sin(polar)
// along the view's azimuth; engineParallaxVector()); the hit's t is its depth along P.
TraceResult godotDeepParallax(const HeightField& field, WrapMode wrap, glm::dvec2 uv0, glm::vec2 P,
                              float cosPolar, const EngineLayers& layers);

// Godot's P for the canonical scene's angles: s sin(polar) (cos azimuth, sin azimuth).
glm::vec2 godotParallaxVector(float scale, double polarDeg, double azimuthDeg);

struct EngineLayersAdvice {
    bool found = false;
    EngineLayers layers;              // found: the smallest that meet the budget
    std::vector<AngleMeasure> angles; // of those layers, or of the most the ladder tried
    EngineLayers tried;               // not found: the most layers measured
    std::string note;                 // one sentence for the export's notes
};

// The smallest Godot min/max layers (max = 4 min, as Godot's 8-32) that meet config's budget at
// every angle up to config.maxPolarDeg, measured as recommend() measures (the same rays, cache and
// confidence). `fallback` names what does meet it when no layer count does (may be empty).
Result<EngineLayersAdvice> recommendGodotLayers(const RecommendConfig& config,
                                                const std::string& fallback = {},
                                                const EvalControl& control = {});

} // namespace px

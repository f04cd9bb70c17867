#pragma once
// The engines' own parallax marches, modelled so their layer counts can be measured and chosen
// like any technique's quality. An engine export cannot ship this project's kernels into the
// engine's standard material; it ships layer counts, and these models say which ones suffice
// (parallax/eval/EngineLayers.h measures them).
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
//
// Unity HDRP (Lit, Pixel displacement; ShaderLibrary/PerPixelDisplacement.hlsl and the Lit's
// ApplyPerPixelDisplacement):
//   viewDirUV = normalize(vec3(view.xy * amplitude, view.z))  amplitude in uv units: s
//   numSteps = int(mix(minSteps, maxSteps, acos(viewDirUV.z) / (pi / 2)))   truncated, <= 256
//   P = viewDirUV.xy / viewDirUV.z = s tan(polar)              the relief's own offset
//   march P / numSteps while the height <= the ray's height, starting one step in, then up to
//   three secant steps between the last two heights (stopping within 0.01 of the surface).
// HDRP offsets by the relief's tan θ, so its march is judged against the relief's exact hit.
// Unreal's ParallaxOcclusionMapping material function has no published formula (its HLSL lives
// in a binary asset): its steps are not modelled, and an Unreal export says so.

#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/trace/Tracer.h"

#include <glm/vec2.hpp>

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

// HDRP's step count for a ray of the relief's offset P (uv units per unit of depth): the
// uv-space view angle is atan|P|.
int hdrpStepCount(const EngineLayers& steps, glm::vec2 P);

// One ray of HDRP's parallax occlusion mapping with the relief's P (s tan(polar)).
TraceResult hdrpParallaxOcclusion(const HeightField& field, WrapMode wrap, glm::dvec2 uv0,
                                  glm::vec2 P, const EngineLayers& steps);

enum class EngineMarch { Godot, Hdrp };

// The most layers (Godot) or steps (HDRP) the engine's material takes: 64 for both. Godot's
// inspector stops heightmap_min_layers and heightmap_max_layers at 64 (material.cpp, range
// "1,64,1"); HDRP Lit clamps _PPDMinSamples and _PPDMaxSamples to Range(1, 64).
inline constexpr int kEngineMaxLayers = 64;

} // namespace px

#pragma once
// The ranges the material file accepts, shared by the JSON reader (type errors name the range)
// and validateMaterial (range errors on materials built in memory), so both say the same thing.

#include "parallax/trace/Technique.h"

namespace px::material {

struct NumberRange {
    double lo;
    double hi;
};

inline constexpr NumberRange kHeightScale{0.0, 100.0};
inline constexpr NumberRange kTiling{0.001, 10000.0};
// technique "auto": p99 budget in texels, steepest view angle in degrees
inline constexpr NumberRange kAutoBudget{0.0, 1e6};
inline constexpr NumberRange kTexelsPerPixel{1e-6, 1e6};
inline constexpr NumberRange kAutoMaxPolar{0.0, 89.0};
inline constexpr NumberRange kUnit{0.0, 1.0}; // softness, roughness, metallic, specular
inline constexpr NumberRange kShininess{1.0, 10000.0};
inline constexpr NumberRange kLightAzimuth{-360.0, 360.0}; // degrees
inline constexpr NumberRange kLightElevation{-90.0, 90.0}; // degrees

struct IntRange {
    int lo;
    int hi;
};

inline constexpr IntRange kLayers{1, kMaxLayersLimit};
inline constexpr IntRange kRefine{0, kMaxRefineLimit};
inline constexpr IntRange kSteps{1, kMaxStepsLimit};

} // namespace px::material

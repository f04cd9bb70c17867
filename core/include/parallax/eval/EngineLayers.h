#pragma once
// The layer counts an engine export ships: the fewest of an engine's own march
// (parallax/engine/EngineMarch.h) that meet an error budget, measured as recommend() measures.

#include "parallax/Result.h"
#include "parallax/engine/EngineMarch.h"
#include "parallax/eval/EvalControl.h"
#include "parallax/eval/Recommendation.h"

#include <string>
#include <vector>

namespace px {

struct EngineLayersAdvice {
    EngineMarch engine = EngineMarch::Godot;
    bool found = false;
    EngineLayers layers;              // found: the smallest that meet the budget
    std::vector<AngleMeasure> angles; // of those layers, or of the most the ladder tried
    EngineLayers tried;               // not found: the most layers measured
    std::string note;                 // one sentence for the export's notes
};

// The smallest min/max layers of an engine's march that meet config's budget at every angle up
// to config.maxPolarDeg, measured as recommend() measures (the same rays, cache and confidence).
// The ladder keeps the engine's default ratio: Godot's 8-32 (max = 4 min), HDRP's 5-15 (max = 3
// min). `fallback` names what does meet the budget when no layer count does (may be empty).
Result<EngineLayersAdvice> recommendEngineLayers(EngineMarch engine, const RecommendConfig& config,
                                                 const std::string& fallback = {},
                                                 const EvalControl& control = {});

inline Result<EngineLayersAdvice> recommendGodotLayers(const RecommendConfig& config,
                                                       const std::string& fallback = {},
                                                       const EvalControl& control = {}) {
    return recommendEngineLayers(EngineMarch::Godot, config, fallback, control);
}

} // namespace px

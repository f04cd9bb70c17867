#pragma once
// The quality settings the bench sweeps for each technique: its cost knob (layers, cone steps, the
// pyramid's node cap) from cheap to expensive, the other parameters at their defaults. Each
// technique's default setting (Technique.cpp) is always one of the points, and `pom` includes the
// tutorial shaders' 8-32 layers, the baseline the project's techniques are measured against.

#include "parallax/Result.h"
#include "parallax/trace/Technique.h"

#include <string>
#include <string_view>
#include <vector>

namespace px {

struct BenchSetting {
    Technique technique = Technique::Exact;
    TraceParams params;
    std::string label; // "layers 8-32, binary 6"; empty for techniques without parameters
    bool isDefault = false;
};

// "layers 8-32", "steps 24", "layers 8-32, binary 6", ...: only the parameters the technique reads.
std::string settingLabel(Technique technique, const TraceParams& params);

// The sweep of one technique, cheapest first.
std::vector<BenchSetting> qualitySweep(Technique technique);

// Only the technique's default setting.
BenchSetting defaultSetting(Technique technique);

// A sweep given by hand, "TECHNIQUE:PARAMETER=V1,V2,...": parameter is layers (MIN-MAX pairs:
// "pom:layers=8-32,16-64"), binary-steps, secant-steps or max-steps; the others keep the
// technique's defaults. Fails on an unknown technique or parameter, one the technique does not
// read, or a value out of range.
Result<std::vector<BenchSetting>> parseSweep(std::string_view spec);

// "all" (every technique that traces rays, `exact` included) or a comma-separated list of names.
// Fails on an unknown name, a repeated one, or `none`/`normal` (they trace nothing).
Result<std::vector<Technique>> parseTechniqueList(std::string_view list);

} // namespace px

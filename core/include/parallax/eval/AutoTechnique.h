#pragma once
// Resolving a material's technique "auto" (Material::autoQuality) where it is rendered or
// exported: the recommendation (Recommendation.h) on the material's own height map, scale and
// wrap, and for Godot and Unity HDRP the layer counts of their own marches (EngineLayers.h).

#include "parallax/Result.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/eval/EngineLayers.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/material/Material.h"
#include "parallax/material/MaterialAssets.h"

#include <optional>
#include <string>

namespace px {

struct ResolvedAuto {
    Material material; // the technique and parameters chosen, autoQuality cleared
    std::string note;  // "technique auto: relaxed-cone (steps 36, binary 4), ..." for the record
    std::optional<EngineLayersAdvice> engineLayers; // when an engine's march was asked for
    std::optional<Recommendation> recommendation;   // what was measured (auto only)
};

// A material without autoQuality comes back unchanged (and no note). Errors: the height map is
// missing or empty, or the recommendation's own (naming `source`); a budget nothing meets.
// `cone` and `relaxedCone` may be empty (baked when a candidate needs them, and kept in
// `coneCacheDir` between runs when it is given: RecommendConfig::cacheDir).
// `used` plus what resolving "auto" reads: the height map, and the cone maps the material has
// files for (candidates that read one are measured with it; a missing one is baked). Render and
// export load this set once, resolve, and use what the choice reads.
MapSet withAutoInputs(const Material& material, MapSet used);

Result<ResolvedAuto> resolveAutoTechnique(const Material& material, const HeightField& height,
                                          const ConeMap& cone, const ConeMap& relaxedCone,
                                          const std::string& source,
                                          std::optional<EngineMarch> engine = std::nullopt,
                                          const std::string& coneCacheDir = {});

} // namespace px

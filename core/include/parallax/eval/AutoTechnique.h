#pragma once
// Resolving a material's technique "auto" (Material::autoQuality) where it is rendered or
// exported: the recommendation (Recommendation.h) on the material's own height map, scale and
// wrap, and for Godot the layer counts of its own march (EngineMarch.h).

#include "parallax/Result.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/eval/EngineMarch.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/material/Material.h"

#include <optional>
#include <string>

namespace px {

struct ResolvedAuto {
    Material material; // the technique and parameters chosen, autoQuality cleared
    std::string note;  // "technique auto: relaxed-cone (steps 36, binary 4), ..." for the record
    std::optional<EngineLayersAdvice> godot; // when asked for
};

// A material without autoQuality comes back unchanged (and no note). Errors: the height map is
// missing or empty, or the recommendation's own (naming `source`); a budget nothing meets.
// `cone` and `relaxedCone` may be empty (baked when a candidate needs them).
Result<ResolvedAuto> resolveAutoTechnique(const Material& material, const HeightField& height,
                                          const ConeMap& cone, const ConeMap& relaxedCone,
                                          const std::string& source, bool godotLayers = false);

} // namespace px

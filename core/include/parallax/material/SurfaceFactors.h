#pragma once
// One rule for a material's roughness and metallic, the same in the preview and every export:
// where the material has a roughness (metallic) map, the map's texel is the value; where it has
// none, its roughness (metallic) number is. A map is never scaled by the number (it once was in
// the preview, which drew a metallic map times the default metallic 0: no metal at all, while
// glTF and Godot drew the map).
//
// Targets that multiply a packed texture by a factor (the preview, the package, glTF, Godot) get
// the rule exactly: a missing map's channel holds 1 and its factor is the number; a present map's
// factor is 1 (surfaceFactors below). Targets that read the texel as the value (Unreal) get the
// number in a missing map's channel, to the texture's 8-bit steps (ExportJob::orm()).

#include "parallax/material/Material.h"

namespace px {

struct SurfaceFactors {
    float roughness = 1.0f;
    float metallic = 1.0f;
};

SurfaceFactors surfaceFactors(const Material& material, bool roughnessMap, bool metallicMap);

} // namespace px

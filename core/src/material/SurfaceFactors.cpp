#include "parallax/material/SurfaceFactors.h"

namespace px {

SurfaceFactors surfaceFactors(const Material& material, bool roughnessMap, bool metallicMap) {
    return {roughnessMap ? 1.0f : material.roughness, metallicMap ? 1.0f : material.metallic};
}

} // namespace px

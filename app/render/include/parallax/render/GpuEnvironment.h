#pragma once
// An environment on the GPU for image-based light (parallax/light/EnvironmentLighting.h): the
// GGX-prefiltered levels as one equirectangular texture's mip chain, the split-sum table and the
// irradiance's nine coefficients. Made once per environment and context; the renderer binds it
// for the variants with VariantKey::environment and for the background.

#include "parallax/Result.h"
#include "parallax/light/EnvironmentLighting.h"
#include "parallax/render/GlObjects.h"
#include "parallax/render/ShaderProgram.h"

#include <memory>

namespace px {

class GpuEnvironment {
public:
    // Needs a current context; fails when a level is larger than the GL allows.
    static Result<std::unique_ptr<GpuEnvironment>> create(const PrefilteredEnvironment& env);

    // Binds the textures to their units and sets pxIrradianceSh and pxEnvMaxLevel.
    void bind(const ShaderProgram& program) const;

private:
    GpuEnvironment() = default;
    gl::Object m_specular;
    gl::Object m_splitSum;
    IrradianceSh m_irradiance{};
    int m_levels = 1;
};

} // namespace px

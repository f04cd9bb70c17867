#include "ShaderBindings.h"

#include "parallax/shader/ShaderGenerator.h"

namespace px::shader {

const std::vector<Binding>& bindings() {
    static const std::vector<Binding> table{
        // Samplers.
        {"pxHeightMap", "sampler2D", TextureUnit::Height},
        {"pxConeMap", "sampler2D", TextureUnit::Cone},
        {"pxMaxMipAtlas", "sampler2D", TextureUnit::MaxMip},
        {"pxAlbedoMap", "sampler2D", TextureUnit::Albedo},
        {"pxNormalMap", "sampler2D", TextureUnit::Normal},
        {"pxOrmMap", "sampler2D", TextureUnit::Orm},
        {"pxRayOrigins", "sampler2D", TextureUnit::RayOrigins},
        {"pxEnvSpecular", "sampler2D", TextureUnit::EnvSpecular},
        {"pxSplitSum", "sampler2D", TextureUnit::SplitSum},
        // The trace kernels' parameters (shaders/trace/common.glsl).
        {"pxScale", "float", -1},
        {"pxHeightMax", "float", -1},
        {"pxMinLayers", "int", -1},
        {"pxMaxLayers", "int", -1},
        {"pxRefineSteps", "int", -1},
        {"pxMaxSteps", "int", -1},
        {"pxMaxMipTop", "int", -1},
        {"pxMaxMipRows", "int[32]", -1},
        {"pxRayP", "vec2", -1},
        // The mesh and the view.
        {"pxModel", "mat4", -1},
        {"pxNormalMatrix", "mat3", -1},
        {"pxViewProjection", "mat4", -1},
        {"pxTiling", "vec2", -1},
        {"pxCameraPos", "vec3", -1},
        // Light and material.
        {"pxLightDir", "vec3", -1},
        {"pxLightColor", "vec3", -1},
        {"pxAmbient", "float", -1},
        {"pxBaseColor", "vec3", -1},
        {"pxSpecular", "float", -1},
        {"pxShininess", "float", -1},
        {"pxRoughness", "float", -1},
        {"pxMetallic", "float", -1},
        {"pxShadowSoftness", "float", -1},
        {"pxNormalGreenSign", "float", -1},
        // The environment (shaders/render/environment.glsl) and the background.
        {"pxIrradianceSh", "vec3[9]", -1},
        {"pxEnvMaxLevel", "float", -1},
        {"pxExposure", "float", -1},
        {"pxInverseViewProjection", "mat4", -1},
    };
    static_assert(kMaxMipAtlasLevels == 32, "pxMaxMipRows is declared int[32]");
    return table;
}

std::string declaration(const Binding& b) {
    std::string type = b.type;
    std::string array;
    if (const std::size_t bracket = type.find('['); bracket != std::string::npos) {
        array = type.substr(bracket);
        type = type.substr(0, bracket);
    }
    std::string d;
    if (b.unit >= 0)
        d = "layout(binding = " + std::to_string(b.unit) + ") ";
    return d + "uniform " + type + " " + b.name + array + ";";
}

} // namespace px::shader

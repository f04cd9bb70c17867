// What each uniform of the package's shader means and the value to set, for README.txt: a
// programmer must be able to draw the material from that file alone (a pxHeightMax left at 0
// makes the relief vanish; a pxLightDir towards the surface instead of the light darkens it).

#include "PackageUniforms.h"

#include "ExportJob.h"
#include "parallax/material/SurfaceFactors.h"

#include <cstdio>
#include <sstream>

namespace px::exporter {

namespace {

std::string number(float value) {
    return formatDecimal(value);
}

std::string vec3Of(float value) {
    return "(" + number(value) + ", " + number(value) + ", " + number(value) + ")";
}

} // namespace

UniformValue uniformValue(const std::string& name, const Material& m, float heightMax) {
    const std::string wrap = m.wrap == WrapMode::Repeat ? "repeat" : "clamp";
    if (name == "pxScale")
        return {"height scale s in uv units (depth of h = 0)", number(m.heightScale), true};
    if (name == "pxHeightMax")
        return {"largest height in the height texture as uploaded; 0 makes the relief vanish, 1 is "
                "safe but slower",
                number(heightMax), true};
    if (name == "pxMinLayers")
        return {"layers looking straight down", std::to_string(m.params.minLayers), true};
    if (name == "pxMaxLayers")
        return {"layers at grazing angles", std::to_string(m.params.maxLayers), true};
    if (name == "pxRefineSteps")
        return {"binary or secant refinement steps",
                std::to_string(refineSteps(m.technique, m.params)), true};
    if (name == "pxMaxSteps")
        return {"cap on cone steps, cells or pyramid nodes", std::to_string(m.params.maxSteps),
                true};
    if (name == "pxMaxMipTop")
        return {"top level of the max-mip pyramid atlas (MaxMipPyramid::top())",
                "from the atlas you build", true};
    if (name == "pxMaxMipRows")
        return {"first row of each level in the atlas (MaxMipPyramid::atlas())",
                "from the atlas you build", true};
    if (name == "pxModel")
        return {"object to world matrix", "your mesh's", true};
    if (name == "pxNormalMatrix")
        return {"inverse transpose of pxModel's upper 3x3", "from pxModel", true};
    if (name == "pxViewProjection")
        return {"projection * view", "your camera's", true};
    if (name == "pxCameraPos")
        return {"camera position, world space", "your camera's", true};
    if (name == "pxTiling")
        return {"uv repeats across the mesh (" + wrap + " wrap)",
                "(" + number(m.tiling) + ", " + number(m.tiling) + ")", true};
    if (name == "pxLightDir")
        return {"unit vector, world space, from the surface TOWARDS the light", "your light's",
                true};
    if (name == "pxLightColor")
        return {"light colour, linear RGB", vec3Of(1.0f) + " (white)", false};
    if (name == "pxAmbient")
        return {"ambient term, fraction of the albedo", "0.12", false};
    if (name == "pxBaseColor")
        return {"linear RGB multiplying the albedo map (the colour where there is none)",
                vec3Of(1.0f), false};
    if (name == "pxSpecular")
        return {"Blinn-Phong specular strength", number(m.specular), false};
    if (name == "pxShininess")
        return {"Blinn-Phong exponent", number(m.shininess), false};
    // The packaged maps multiply these: 1 where a map is packaged (SurfaceFactors.h).
    const SurfaceFactors surface =
        surfaceFactors(m, !m.maps.roughness.empty(), !m.maps.metallic.empty());
    if (name == "pxRoughness")
        return {"multiplies the roughness channel: the roughness where there is no roughness map, "
                "1 where there is",
                number(surface.roughness), false};
    if (name == "pxMetallic")
        return {"multiplies the metallic channel: the metallic where there is no metallic map, 1 "
                "where there is",
                number(surface.metallic), false};
    if (name == "pxShadowSoftness")
        return {"self-shadow softness, 0 hard to 1 very soft", number(m.shadowSoftness), false};
    if (name == "pxNormalGreenSign")
        return {"+1 for an OpenGL (Y+) normal map, -1 for DirectX (Y-)",
                m.normalGreen == NormalGreen::DirectX ? "-1" : "1", true};
    return {"", "", false};
}

const char* unitFormat(int unit) {
    switch (unit) {
    case TextureUnit::Height:
        return "GL_R16 (GL_R32F for .exr), mipmapped (glGenerateMipmap), GL_LINEAR_MIPMAP_LINEAR, "
               "magnification GL_LINEAR: the shader filters heights in hardware (textureGrad, "
               "textureGather); never 8-bit";
    case TextureUnit::Cone:
        return "GL_RG32F (R height, G sqrt(cone ratio)), one level, GL_LINEAR (the shader "
               "filters it in hardware)";
    case TextureUnit::MaxMip:
        return "GL_R32F max-mip pyramid atlas built from the height map when loading "
               "(MaxMipPyramid::atlas()), one level, GL_NEAREST";
    case TextureUnit::Albedo:
        return "sRGB-encoded: GL_SRGB8_ALPHA8 (decoded to linear on sampling), mipmapped, "
               "GL_LINEAR_MIPMAP_LINEAR";
    case TextureUnit::Normal:
        return "GL_RGBA16 (GL_RGBA8 rounds every mip level to 8 bits, which moves specular "
               "highlights by up to 10 of 255 steps), linear (never sRGB), mipmapped, "
               "GL_LINEAR_MIPMAP_LINEAR";
    case TextureUnit::Orm:
        return "GL_RGBA16, linear: occlusion (R), roughness (G), metallic (B), mipmapped, "
               "GL_LINEAR_MIPMAP_LINEAR";
    default:
        return "";
    }
}

} // namespace px::exporter

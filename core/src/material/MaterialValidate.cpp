// validateMaterial: the value rules of the material file, on a material in memory.

#include "MaterialLimits.h"
#include "MaterialText.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/material/MaterialNames.h"

#include <cmath>

namespace px {

using namespace material;

std::vector<MaterialProblem> validateMaterial(const Material& m, MaterialCheck check) {
    std::vector<MaterialProblem> problems;
    auto number = [&](const char* pointer, float value, NumberRange range) {
        if (!std::isfinite(value) || value < range.lo || value > range.hi)
            problems.push_back({pointer, expectedNumber(range) + ", got " + numberText(value)});
    };
    auto integer = [&](const char* pointer, int value, IntRange range) {
        if (value < range.lo || value > range.hi)
            problems.push_back(
                {pointer, expectedInteger(range) + ", got " + std::to_string(value)});
    };

    if (m.name.empty())
        problems.push_back({"/name", "expected a non-empty name"});
    number("/height/scale", m.heightScale, kHeightScale);
    if (m.heightRange && !(std::isfinite(m.heightRange->lo) && std::isfinite(m.heightRange->hi) &&
                           m.heightRange->lo < m.heightRange->hi))
        problems.push_back({"/height/range", "expected lo < hi (the file values for heights 0 "
                                             "and 1), got [" +
                                                 numberText(m.heightRange->lo) + ", " +
                                                 numberText(m.heightRange->hi) + "]"});
    number("/tiling", m.tiling, kTiling);
    integer("/technique/minLayers", m.params.minLayers, kLayers);
    integer("/technique/maxLayers", m.params.maxLayers, kLayers);
    integer("/technique/binarySteps", m.params.binarySteps, kRefine);
    integer("/technique/secantSteps", m.params.secantSteps, kRefine);
    integer("/technique/maxSteps", m.params.maxSteps, kSteps);
    if (m.params.minLayers > m.params.maxLayers && m.params.minLayers >= kLayers.lo &&
        m.params.maxLayers <= kLayers.hi)
        problems.push_back({"/technique/minLayers", "min layers (" +
                                                        std::to_string(m.params.minLayers) +
                                                        ") exceed max layers (" +
                                                        std::to_string(m.params.maxLayers) + ")"});
    number("/shadow/softness", m.shadowSoftness, kUnit);
    number("/lighting/roughness", m.roughness, kUnit);
    number("/lighting/metallic", m.metallic, kUnit);
    number("/lighting/specular", m.specular, kUnit);
    number("/lighting/shininess", m.shininess, kShininess);
    if (m.light) {
        number("/light/azimuth", m.light->azimuthDeg, kLightAzimuth);
        number("/light/elevation", m.light->elevationDeg, kLightElevation);
    }

    // The maps the technique and the normal source read must be there.
    if (check == MaterialCheck::Preset)
        return problems;
    const TechniqueInfo& technique = info(m.technique);
    if (m.maps.height.empty()) {
        if (technique.parallax)
            problems.push_back({"/maps/height", "technique \"" + std::string(technique.name) +
                                                    "\" needs a height map"});
        else if (m.normalSource == NormalSource::HeightCentral ||
                 m.normalSource == NormalSource::HeightSobel)
            problems.push_back({"/maps/height", "normal source \"" +
                                                    std::string(toString(m.normalSource)) +
                                                    "\" needs a height map"});
    }
    if (m.normalSource == NormalSource::Map && m.maps.normal.empty())
        problems.push_back({"/maps/normal", "normal source \"map\" needs a normal map"});
    return problems;
}

std::string formatProblems(const std::vector<MaterialProblem>& problems,
                           const std::string& source) {
    std::string text;
    for (const MaterialProblem& p : problems) {
        if (!text.empty())
            text += '\n';
        text += source + ": ";
        if (!p.pointer.empty())
            text += p.pointer + ": ";
        text += p.message;
    }
    return text;
}

} // namespace px

#pragma once
// Tracing one ray with one technique on the CPU. The techniques are the GLSL kernels of
// shaders/trace/ compiled as C++ (see shaders/trace/README.md), so the GPU runs the same code.

#include "parallax/Result.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/trace/Technique.h"

#include <glm/vec2.hpp>
#include <memory>
#include <optional>

namespace px {

// What a ray found: the hit uv (not wrapped), its normalised depth t (uv = uv0 + P t), and the
// number of fetches the technique made. t is always in [0, 1] and never NaN.
struct TraceResult {
    double u = 0.0;
    double v = 0.0;
    float t = 0.0f;
    int fetches = 0;
};

// The maps a technique reads. A technique needs only some of them (info(technique)).
struct TraceMaps {
    const HeightField* height = nullptr;
    WrapMode wrap = WrapMode::Repeat;
    const ConeMap* cone = nullptr;
    const ConeMap* relaxedCone = nullptr;
    const MaxMipPyramid* pyramid = nullptr;
    // The height map's maximum if the caller knows it (a recommendation makes dozens of tracers
    // of one map); else create() scans the map for it.
    std::optional<float> heightMax;
};

// Owns the derived maps a technique needs that the caller did not supply (baked on demand).
class Tracer {
public:
    // Fails if the height field is empty, a parameter is out of range, or a supplied map does not
    // match the height field's size or wrap mode.
    static Result<Tracer> create(const TraceMaps& maps, Technique technique,
                                 const TraceParams& params, float heightScale);

    // uv0 in double so tiled coordinates far from the origin (4096.3) keep their precision: with
    // repeat the integer part is set aside before marching and added back to the hit.
    // P = s * d.xy / (-d.z) (docs/conventions.md §2); it must be finite.
    TraceResult trace(glm::dvec2 uv0, glm::vec2 P) const;

    // From now on, trace with the production kernels (the GPU's default flavour) on a model of a
    // GPU texture unit whose bilinear weights keep `subTexelBits` fractional bits (8 on most GPUs):
    // what hardware filtering costs, measured on the CPU. 0 (the default): the exact kernels.
    void modelTextureUnit(int subTexelBits) { m_subTexelBits = subTexelBits; }

    Technique technique() const { return m_technique; }
    const TraceParams& params() const { return m_params; }
    float heightScale() const { return m_scale; }
    const HeightField& heightField() const { return *m_maps.height; }

private:
    Tracer() = default;
    template <typename Kernel> TraceResult traceWith(Kernel& k, glm::dvec2 uv0, glm::vec2 P) const;
    TraceMaps m_maps;
    Technique m_technique = Technique::Exact;
    TraceParams m_params;
    float m_scale = 0.0f;
    float m_heightMax = 1.0f;
    int m_subTexelBits = 0;
    std::shared_ptr<const ConeMap> m_ownedCone;
    std::shared_ptr<const MaxMipPyramid> m_ownedPyramid;
};

// Checks a parameter set against the limits in Technique.h; the message names the parameter.
Status validate(const TraceParams& params);

} // namespace px

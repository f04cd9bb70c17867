#include "parallax/trace/Tracer.h"

#include "HardwareModelKernel.h"
#include "TraceKernel.h"
#include "parallax/bake/ConeMapBaker.h"

#include <cmath>
#include <string>

namespace px {

Status validate(const TraceParams& p) {
    auto range = [](const char* name, int value, int lo, int hi) -> Status {
        if (value < lo || value > hi)
            return Error{std::string(name) + " is " + std::to_string(value) + ", expected " +
                         std::to_string(lo) + " to " + std::to_string(hi)};
        return success();
    };
    for (Status s : {range("min layers", p.minLayers, 1, kMaxLayersLimit),
                     range("max layers", p.maxLayers, 1, kMaxLayersLimit),
                     range("binary steps", p.binarySteps, 0, kMaxRefineLimit),
                     range("secant steps", p.secantSteps, 0, kMaxRefineLimit),
                     range("max steps", p.maxSteps, 1, kMaxStepsLimit)}) {
        if (!s)
            return s;
    }
    if (p.minLayers > p.maxLayers)
        return Error{"min layers (" + std::to_string(p.minLayers) + ") exceed max layers (" +
                     std::to_string(p.maxLayers) + ")"};
    return success();
}

Result<Tracer> Tracer::create(const TraceMaps& maps, Technique technique, const TraceParams& params,
                              float heightScale) {
    if (!maps.height || maps.height->empty())
        return Error{"the height map is empty"};
    if (!std::isfinite(heightScale) || heightScale < 0.0f)
        return Error{"the height scale must be a finite number >= 0"};
    if (Status s = validate(params); !s)
        return s.error();

    Tracer tracer;
    tracer.m_maps = maps;
    tracer.m_technique = technique;
    tracer.m_params = params;
    tracer.m_scale = heightScale;
    tracer.m_heightMax = maps.heightMax ? *maps.heightMax : maps.height->maxHeight();

    const TechniqueInfo& ti = info(technique);
    const HeightField& field = *maps.height;
    auto sameSize = [&](const ConeMap* cones) {
        return cones->width == field.width && cones->height == field.height;
    };
    if (ti.needsConeMap || ti.needsRelaxedConeMap) {
        const ConeKind kind = ti.needsConeMap ? ConeKind::Conservative : ConeKind::Relaxed;
        const ConeMap* given = ti.needsConeMap ? maps.cone : maps.relaxedCone;
        if (given && !sameSize(given))
            return Error{"the cone map's size differs from the height map's"};
        if (!given) {
            tracer.m_ownedCone = std::make_shared<ConeMap>(bakeConeMap(field, maps.wrap, kind));
            given = tracer.m_ownedCone.get();
        }
        (ti.needsConeMap ? tracer.m_maps.cone : tracer.m_maps.relaxedCone) = given;
    }
    if (ti.needsPyramid) {
        if (maps.pyramid && (maps.pyramid->wrap() != maps.wrap || maps.pyramid->levels() == 0))
            return Error{"the max-mip pyramid was built for another wrap mode"};
        if (!maps.pyramid) {
            tracer.m_ownedPyramid =
                std::make_shared<MaxMipPyramid>(MaxMipPyramid::build(field, maps.wrap));
            tracer.m_maps.pyramid = tracer.m_ownedPyramid.get();
        }
    }
    return tracer;
}

TraceResult Tracer::trace(glm::dvec2 uv0, glm::vec2 rawP) const {
    if (m_subTexelBits > 0) {
        kernel::HardwareModelKernel k;
        k.subTexelBits = m_subTexelBits;
        return traceWith(k, uv0, rawP);
    }
    kernel::TraceKernel k;
    return traceWith(k, uv0, rawP);
}

template <typename Kernel>
TraceResult Tracer::traceWith(Kernel& k, glm::dvec2 uv0, glm::vec2 rawP) const {
    const HeightField& field = *m_maps.height;
    k.pxMapSize = glm::ivec2(field.width, field.height);
    k.pxWrapRepeat = m_maps.wrap == WrapMode::Repeat;
    k.pxHeightMax = m_heightMax;
    k.pxScale = m_scale;
    k.pxMinLayers = m_params.minLayers;
    k.pxMaxLayers = m_params.maxLayers;
    k.pxRefineSteps = refineSteps(m_technique, m_params);
    k.pxMaxSteps = m_params.maxSteps;
    k.heightField = &field;
    k.pyramid = m_maps.pyramid;
    k.pxMaxMipTop = m_maps.pyramid ? m_maps.pyramid->top() : 0;
    k.coneMap = m_technique == Technique::Cone ? m_maps.cone : m_maps.relaxedCone;

    // Far from the origin float uv loses the texel: march from the fractional part (repeat only;
    // with clamp the position relative to the tile is the point).
    const glm::dvec2 base = k.pxWrapRepeat ? glm::floor(uv0) : glm::dvec2(0.0);
    const glm::vec2 local(uv0 - base);
    const glm::vec2 P = k.pxBoundParallax(rawP);
    const bool parallax = info(m_technique).parallax;
    float t = 0.0f;
    if (!parallax) {
        t = 0.0f;
    } else if (k.pxLooksStraightDown(P)) {
        t = k.pxTraceStraightDown(local);
    } else {
        switch (m_technique) {
        case Technique::Offset:
            t = k.pxTraceOffset(local, P);
            break;
        case Technique::Steep:
            t = k.pxTraceSteep(local, P);
            break;
        case Technique::Pom:
            t = k.pxTracePom(local, P);
            break;
        case Technique::Relief:
            t = k.pxTraceRelief(local, P);
            break;
        case Technique::Secant:
            t = k.pxTraceSecant(local, P);
            break;
        case Technique::Cone:
            t = k.pxTraceCone(local, P);
            break;
        case Technique::RelaxedCone:
            t = k.pxTraceRelaxedCone(local, P);
            break;
        case Technique::Pyramid:
            t = k.pxTracePyramid(local, P);
            break;
        case Technique::Exact:
            t = k.pxTraceExact(local, P);
            break;
        case Technique::None:
        case Technique::Normal:
            break;
        }
    }
    t = k.pxKeepT(t);
    TraceResult r;
    r.u = uv0.x + static_cast<double>(P.x) * t;
    r.v = uv0.y + static_cast<double>(P.y) * t;
    r.t = t;
    r.fetches = k.pxFetches;
    return r;
}

} // namespace px

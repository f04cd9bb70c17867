#include "parallax/render/GpuTracer.h"

#include "parallax/bake/ConeMapBaker.h"
#include "parallax/render/FrameTimer.h"
#include "parallax/render/GlInfo.h"
#include "parallax/render/RenderTarget.h"
#include "parallax/render/TextureUpload.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <algorithm>
#include <cmath>
#include <optional>

namespace px {

namespace {

// traceSceneGpu's work: `warmup` untimed draws, then `frames` timed ones; the hits are read back
// only when `hits` is given.
Status traceOnGpu(ShaderCache& shaders, const TraceMaps& maps, Technique technique,
                  const TraceParams& params, float heightScale, const TraceScene& scene, int frames,
                  int warmup, KernelFlavour kernels, GpuTraceTiming& timing,
                  std::vector<TraceResult>* hits) {
    if (Status s = validate(scene); !s)
        return s.error();
    // The CPU tracer's checks, and its choice of derived maps.
    Result<Tracer> cpu = Tracer::create(maps, technique, params, heightScale);
    if (!cpu)
        return cpu.error();
    const HeightField& field = *maps.height;
    const TechniqueInfo& ti = info(technique);
    const int R = scene.rays;

    VariantKey key;
    key.technique = technique;
    key.wrap = maps.wrap;
    key.output = ShaderOutput::Trace;
    key.flavour = kernels;
    Result<const ShaderProgram*> program = shaders.program(key);
    if (!program)
        return program.error();
    const ShaderProgram& p = **program;

    // uv0 per ray as the CPU traces it: the double origin, reduced to the tile with repeat. The
    // tile bases are kept only to return the hits (a timing reads none back).
    const bool repeat = maps.wrap == WrapMode::Repeat;
    std::vector<float> origins(static_cast<std::size_t>(R) * R * 2);
    std::vector<glm::dvec2> bases(hits ? static_cast<std::size_t>(R) * R : 0);
    for (int j = 0; j < R; ++j) {
        for (int i = 0; i < R; ++i) {
            const glm::dvec2 uv0 = rayOrigin(scene, i, j);
            const glm::dvec2 base = repeat ? glm::floor(uv0) : glm::dvec2(0.0);
            const glm::vec2 local(uv0 - base);
            const std::size_t k = static_cast<std::size_t>(j) * R + i;
            origins[2 * k] = local.x;
            origins[2 * k + 1] = local.y;
            if (hits)
                bases[k] = base;
        }
    }

    Result<gl::Object> height = gl::uploadHeight(field, gl::HeightFormat::R32F);
    if (!height)
        return height.error();
    gl::setWrap(*height, maps.wrap);
    Result<gl::Object> rays = gl::uploadRg32f(R, R, origins);
    if (!rays)
        return rays.error();
    gl::Object cone, atlas;
    std::vector<int> rows;
    std::optional<ConeMap> bakedCone;
    std::optional<MaxMipPyramid> bakedPyramid;
    if (ti.needsConeMap || ti.needsRelaxedConeMap) {
        const ConeMap* given = ti.needsConeMap ? maps.cone : maps.relaxedCone;
        if (!given) {
            bakedCone = bakeConeMap(field, maps.wrap,
                                    ti.needsConeMap ? ConeKind::Conservative : ConeKind::Relaxed);
            given = &*bakedCone;
        }
        Result<gl::Object> t = gl::uploadConeMap(field, *given, gl::ConeFormat::RG32F);
        if (!t)
            return t.error();
        gl::setWrap(*t, maps.wrap);
        cone = std::move(*t);
    }
    int top = 0;
    if (ti.needsPyramid) {
        const MaxMipPyramid* given = maps.pyramid;
        if (!given) {
            bakedPyramid = MaxMipPyramid::build(field, maps.wrap);
            given = &*bakedPyramid;
        }
        Result<gl::Object> t = gl::uploadMaxMipAtlas(*given, rows);
        if (!t)
            return t.error();
        atlas = std::move(*t);
        top = given->top();
    }

    Result<RenderTarget> target = RenderTarget::create({R, R}, TargetFormat::Rgba32F);
    if (!target)
        return target.error();
    const glm::vec2 P = parallaxVector(heightScale, scene.polarDeg, scene.azimuthDeg);
    p.set("pxRayP", P);
    p.set("pxScale", heightScale);
    p.set("pxHeightMax", field.maxHeight());
    p.set("pxMinLayers", params.minLayers);
    p.set("pxMaxLayers", params.maxLayers);
    p.set("pxRefineSteps", refineSteps(technique, params));
    p.set("pxMaxSteps", params.maxSteps);
    p.set("pxMaxMipTop", top);
    if (!rows.empty())
        p.set("pxMaxMipRows", std::span<const int>(rows));
    auto bindUnit = [](int unit, const gl::Object& t) {
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
        glBindTexture(GL_TEXTURE_2D, t.id());
    };
    bindUnit(TextureUnit::Height, *height);
    bindUnit(TextureUnit::RayOrigins, *rays);
    if (cone)
        bindUnit(TextureUnit::Cone, cone);
    if (atlas)
        bindUnit(TextureUnit::MaxMip, atlas);
    glActiveTexture(GL_TEXTURE0);

    gl::Object vertexArray(gl::ObjectKind::VertexArray);
    target->bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    p.use();
    glBindVertexArray(vertexArray.id());
    const FrameTiming t =
        timeFrames([] { glDrawArrays(GL_TRIANGLES, 0, 3); }, frames, warmup, currentGlInfo());
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (Status s = checkGlError("tracing on the GPU"); !s)
        return s.error();
    timing.milliseconds = t.minMs;
    timing.gpuTimer = t.gpuTimer;
    timing.renderer = currentGlInfo().renderer;
    if (!hits)
        return success();

    // read() puts GL's bottom row (ray row 0) last.
    const Image out = target->read();
    std::vector<TraceResult>& results = *hits;
    results.assign(static_cast<std::size_t>(R) * R, TraceResult{});
    for (int j = 0; j < R; ++j) {
        for (int i = 0; i < R; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * R + i;
            const int row = R - 1 - j;
            TraceResult& r = results[k];
            r.u = bases[k].x + out.at(i, row, 0);
            r.v = bases[k].y + out.at(i, row, 1);
            r.t = out.at(i, row, 2);
            r.fetches = static_cast<int>(std::lround(out.at(i, row, 3)));
        }
    }
    return success();
}

} // namespace

Result<std::vector<TraceResult>> traceSceneGpu(ShaderCache& shaders, const TraceMaps& maps,
                                               Technique technique, const TraceParams& params,
                                               float heightScale, const TraceScene& scene,
                                               GpuTraceTiming* timing, KernelFlavour kernels) {
    GpuTraceTiming measured;
    std::vector<TraceResult> hits;
    if (Status s = traceOnGpu(shaders, maps, technique, params, heightScale, scene, 1, 0, kernels,
                              measured, &hits);
        !s)
        return s.error();
    if (timing)
        *timing = measured;
    return hits;
}

Result<GpuTraceTiming> timeSceneGpu(ShaderCache& shaders, const TraceMaps& maps,
                                    Technique technique, const TraceParams& params,
                                    float heightScale, const TraceScene& scene, int frames,
                                    KernelFlavour kernels) {
    GpuTraceTiming measured;
    if (Status s = traceOnGpu(shaders, maps, technique, params, heightScale, scene,
                              std::max(frames, 1), 1, kernels, measured, nullptr);
        !s)
        return s.error();
    return measured;
}

} // namespace px

#include "parallax/render/HeadlessContext.h"

namespace px {

Result<std::vector<TraceResult>> traceSceneHeadless(const TraceMaps& maps, Technique technique,
                                                    const TraceParams& params, float heightScale,
                                                    const TraceScene& scene, GpuTraceTiming* timing,
                                                    KernelFlavour kernels) {
    Result<std::unique_ptr<HeadlessContext>> context = HeadlessContext::create();
    if (!context)
        return context.error();
    ShaderCache shaders;
    return traceSceneGpu(shaders, maps, technique, params, heightScale, scene, timing, kernels);
}

} // namespace px

#pragma once
// The bridge between a viewport's PreviewScene and the GL renderer (parallax-render): uploads the
// maps when they change, draws the scene (and the A/B wipe's second technique), and measures the
// view's figures against the exact intersection with the renderer's surface output.
// Every call needs the preview's GL context current.

#include "parallax/Result.h"
#include "parallax/image/Image.h"
#include "preview/FramePacer.h"
#include "preview/PreviewScene.h"

#include <QImage>
#include <QSize>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

namespace px {
class GpuMaterial;
class ShaderCache;
} // namespace px

namespace px::studio {

class PreviewRenderer {
public:
    static Result<std::unique_ptr<PreviewRenderer>> create();
    ~PreviewRenderer();

    // Draws into framebuffer `fbo` of `pixels` device pixels; returns the frame time in ms
    // (steady clock around the draw and glFinish).
    Result<double> draw(const PreviewScene& scene, QSize pixels, unsigned fbo);
    // A turn of the event loop's share of the frame of `scene` (FramePacer.h): drawn in bands
    // into the view's own target and shown in `fbo` once whole, a smaller picture meanwhile.
    // `serial` changes whenever the scene or the size does; a `budgetMs` of 0 draws nothing.
    Result<FramePacer::Step> drawStep(const PreviewScene& scene, std::uint64_t serial, QSize pixels,
                                      unsigned fbo, double budgetMs);
    // Fetches per pixel, the technique's error and the filtering's (ErrorStats.h), rendered at
    // the view's own resolution (the marching techniques' height level follows each pixel's
    // footprint): over every pixel when the heat map is on (and makes it), else over a
    // stratified sample of boxes of the view; a pixel counts where the exact hits lie on the
    // surface the view shows (VisibleRegion.h). Three extra passes (the technique's hits in the
    // verify kernels, exact on the footprint's level and on level 0; at 8192² 0.3-0.6 s on
    // llvmpipe) and a cheap one of the surface's own uv over the whole view (no tracing): drawn
    // a slice at a time, so the event loop runs between.
    // beginMeasure() starts over; each measureStep() draws at least one box, and no box it
    // expects to take it past `sliceMs` (measureBoxMs: the dearest box so far), and returns the
    // figures once every pass is done (not valid while the maps upload), else nothing yet.
    Status beginMeasure(const PreviewScene& scene, QSize pixels, double frameMs);
    std::optional<Result<PreviewStats>> measureStep(double sliceMs);
    double measureBoxMs() const;
    void cancelMeasure();
    bool measuring() const;
    // The last measureStep drew nothing: its next pass's variant waits for the user to pause
    // (FramePacer::inputRecently), as a frame's does.
    bool measureWaitsForInput() const;
    QImage heatMap() const { return m_heatMap; }
    // The last measurement's renders (entry uv, the technique's hits, exact on the footprint's
    // level, exact on level 0), kept once asked for: tests trace the same rays on the CPU.
    struct Surfaces {
        Image entry, hits, footprintExact, exact;
    };
    void keepSurfaces(bool keep) { m_keepSurfaces = keep; }
    const Surfaces& surfaces() const { return m_surfaces; }
    std::optional<float> uniformValue(const std::string& name);
    // The maps this view last drew with (views showing the same maps share one), for tests.
    const GpuMaterial* gpuMaterial() const;
    // The compiled variants this view draws with, shared by every view (tests).
    const ShaderCache& shaders() const;

    // Big maps go up on a worker (jobs/MapUpload.h): meanwhile draw() shows the maps there are
    // (or the background, where they cannot stand in) and measure() measures nothing.
    bool uploading() const;
    bool mapsArrived() const; // the worker is done: the next frame draws the scene's maps
    void waitForMaps();       // blocks until the worker is done (then draw again)
    // Uploads of more texels than this go to the worker (4096² by default; tests lower it).
    static void setBackgroundUploadTexels(std::size_t texels);

private:
    PreviewRenderer() = default;
    Result<bool> prepare(const PreviewScene& scene);
    Status drawScene(const PreviewScene& scene, glm::ivec2 size, QRect rows);
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    QImage m_heatMap;
    bool m_keepSurfaces = false;
    Surfaces m_surfaces;
    FramePacer m_pacer;
};

} // namespace px::studio

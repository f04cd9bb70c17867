#include "preview/PreviewRenderer.h"

#include "jobs/MapUpload.h"
#include "parallax/io/Fnv1a.h"
#include "parallax/render/GpuEnvironment.h" // parallax-render
#include "parallax/render/Renderer.h"       // parallax-render
#include "preview/ErrorStats.h"
#include "preview/VisibleRegion.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFunctions>
#include <QRect>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace px::studio {

namespace {

// Without the heat map the figures come from a stratified sample of the view: a box in each
// cell of a 6 x 4 grid, about this many pixels in all. Enough for a p99 (the worst 1 % is still
// hundreds of pixels), few enough for llvmpipe to trace `exact` in a moment.
constexpr int kSamplePixels = 40000;

std::vector<QRect> sampleBoxes(int width, int height) {
    constexpr int columns = 6, rows = 4;
    const int cellW = std::max(1, width / columns), cellH = std::max(1, height / rows);
    const double fraction =
        std::min(1.0, std::sqrt(double(kSamplePixels) / (double(width) * height)));
    const int boxW = std::max(1, int(cellW * fraction)), boxH = std::max(1, int(cellH * fraction));
    std::vector<QRect> boxes;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i)
            boxes.emplace_back(i * cellW + (cellW - boxW) / 2, j * cellH + (cellH - boxH) / 2, boxW,
                               boxH);
    return boxes;
}

// The whole view for the heat map, in bands of about this many pixels: a slice of the measurement
// draws whole bands, and at 8192² one band of `exact` costs llvmpipe a few tens of ms.
constexpr int kBandPixels = 8192;

std::vector<QRect> bands(int width, int height) {
    const int rows = std::max(1, kBandPixels / width);
    std::vector<QRect> boxes;
    for (int y = 0; y < height; y += rows)
        boxes.emplace_back(0, y, width, std::min(rows, height - y));
    return boxes;
}

// A dark neutral backdrop, sRGB-encoded as the colour output is.
constexpr glm::vec4 kBackground{0.16f, 0.17f, 0.19f, 1.0f};

QOpenGLFunctions* gl() {
    return QOpenGLContext::currentContext()->functions();
}

// A material's maps on the GPU, for every view that shows them: the views' contexts share their
// textures (AA_ShareOpenGLContexts, GlSupport.cpp), so two views of an 8192² map hold one copy.
struct Upload {
    std::shared_ptr<const MaterialAssets> assets;
    WrapMode wrap = WrapMode::Repeat;
    std::shared_ptr<GpuMaterial> gpu;
};

// The uploads some view still holds (GUI thread only, where every view draws).
std::vector<std::weak_ptr<Upload>>& liveUploads() {
    static std::vector<std::weak_ptr<Upload>> uploads;
    std::erase_if(uploads, [](const std::weak_ptr<Upload>& u) { return u.expired(); });
    return uploads;
}

// The uploads running on a worker for some view (one per map set: a second view waits on it).
std::vector<std::weak_ptr<MapUpload>>& runningUploads() {
    static std::vector<std::weak_ptr<MapUpload>> uploads;
    std::erase_if(uploads, [](const std::weak_ptr<MapUpload>& u) { return u.expired(); });
    return uploads;
}

// The compiled variants of the views whose contexts share objects (AA_ShareOpenGLContexts: every
// view's), one cache per share group: a variant compiles once however many views draw it. A new
// view (Ctrl+4 opens three) used to compile every variant it drew again, on the GUI thread.
std::shared_ptr<ShaderCache> groupShaderCache() {
    static std::map<const QOpenGLContextGroup*, std::weak_ptr<ShaderCache>> caches;
    std::erase_if(caches, [](const auto& entry) { return entry.second.expired(); });
    const QOpenGLContextGroup* group = QOpenGLContext::currentContext()->shareGroup();
    std::shared_ptr<ShaderCache> cache = caches[group].lock();
    if (!cache) {
        cache = std::make_shared<ShaderCache>();
        caches[group] = cache;
    }
    return cache;
}

// Uploads of more texels than this go up on a worker (jobs/MapUpload.h): 4096², about 0.3 s on
// the GUI thread with llvmpipe.
std::size_t g_backgroundTexels = std::size_t(4096) * 4096;

// A measurement under way, drawn a few boxes at a time into the surface target (u, v, t,
// fetches; -1 outside the boxes): each pixel's own uv over the whole view (no tracing: what the
// view shows, VisibleRegion.h), then in the boxes the view's hits, exact's on the height level
// the view's technique reads, and exact's on level 0 (ErrorStats.h).
struct Measurement {
    enum class Pass { Entry, View, FootprintExact, Exact };
    PreviewScene scene;
    double frameMs = 0.0;
    std::vector<QRect> boxes; // the view's and exact's passes
    std::vector<QRect> whole; // the entry pass
    std::size_t next = 0;     // the next box of the pass to draw
    Pass pass = Pass::Entry;
    Image entry, hits, footprint; // the first three passes' output
    double boxMs = 0.0;           // the dearest box drawn so far (a pass's last box reads it back)
    const std::vector<QRect>& passBoxes() const { return pass == Pass::Entry ? whole : boxes; }
};

PreviewStats statsOf(const SurfaceErrors& errors) {
    PreviewStats stats;
    stats.fetchesPerPixel = errors.meanFetches;
    stats.meanError = errors.techniqueError.mean;
    stats.p99Error = errors.techniqueError.p99;
    stats.maxError = errors.techniqueError.max;
    stats.otherSurfaceShare = errors.techniqueError.otherSurfaceShare;
    stats.otherSurface = errors.otherSurface;
    stats.filteringMeanError = errors.filteringError.mean;
    stats.filteringP99Error = errors.filteringError.p99;
    stats.filteringMaxError = errors.filteringError.max;
    stats.pixels = errors.pixels;
    stats.area = errors.area;
    stats.steepPixels = errors.steepPixels;
    stats.offRegionPixels = errors.offRegionPixels;
    stats.valid = true;
    return stats;
}

} // namespace

struct PreviewRenderer::Impl {
    std::unique_ptr<Renderer> renderer;
    std::shared_ptr<Upload> upload;            // the maps this view draws with
    GpuMaterial* gpu = nullptr;                // upload's
    std::shared_ptr<MapUpload> pending;        // the scene's maps going up on a worker meanwhile
    std::optional<VariantKey> lastKey;         // the variant of the last frame (uniformValue)
    std::optional<RenderTarget> surfaceTarget; // float (u, v, t, fetches), the view's size
    std::shared_ptr<const PrefilteredEnvironment> uploadedEnvironment; // what gpuEnvironment holds
    std::unique_ptr<GpuEnvironment> gpuEnvironment;
    // The variants this view's context has drawn: a new one's first draw is put off while the
    // user acts (FramePacer::inputRecently), as llvmpipe compiles it for this context then.
    std::set<std::uint32_t> drawnVariants;
    bool shownOnce = false;    // a whole frame has been shown
    bool measureWaits = false; // the measurement's next pass waits for the user to pause

    bool waitForInputPause(const std::vector<VariantKey>& keys) const {
        return FramePacer::inputRecently() && std::ranges::any_of(keys, [&](const VariantKey& k) {
                   return !drawnVariants.contains(k.bits());
               });
    }
    void drew(const std::vector<VariantKey>& keys) {
        for (const VariantKey& k : keys)
            drawnVariants.insert(k.bits());
    }

    Status syncEnvironment(const PreviewScene& scene) {
        if (uploadedEnvironment == scene.view.environment)
            return success();
        gpuEnvironment.reset();
        uploadedEnvironment = scene.view.environment;
        if (!uploadedEnvironment)
            return success();
        Result<std::unique_ptr<GpuEnvironment>> made = GpuEnvironment::create(*uploadedEnvironment);
        if (!made)
            return made.error();
        gpuEnvironment = std::move(*made);
        return success();
    }

    // Uploads the scene's maps when they are not the ones on the GPU: takes another view's upload
    // of the same maps, else makes one that keeps the textures of the maps that did not change
    // (after a bake only the new map goes up; after an undo, none).
    Status sync(const PreviewScene& scene) {
        const WrapMode wrap = scene.material.wrap;
        const std::vector<Technique> wanted = techniques(scene);
        auto fits = [&](const std::shared_ptr<Upload>& u) {
            return u && u->assets == scene.assets && u->wrap == wrap;
        };
        auto ready = [&](const std::shared_ptr<Upload>& u) {
            return std::all_of(wanted.begin(), wanted.end(),
                               [&](Technique t) { return u->gpu->ready(t); });
        };
        if (fits(upload) && ready(upload)) {
            pending.reset();
            return success();
        }
        std::vector<std::weak_ptr<Upload>>& uploads = liveUploads();
        std::shared_ptr<Upload> previous = upload;
        for (const std::weak_ptr<Upload>& weak : uploads) {
            std::shared_ptr<Upload> other = weak.lock();
            if (fits(other) && ready(other)) {
                adopt(other);
                return success();
            }
            if (other && (!previous || (fits(other) && !fits(previous))))
                previous = other; // the textures to take over: the same maps' if any
        }
        const std::shared_ptr<Upload> fitting = fits(previous) ? previous : nullptr;
        const GpuMaterial* reuse = previous ? previous->gpu.get() : nullptr;
        if (pending && (pending->assets() != scene.assets || pending->wrap() != wrap))
            pending.reset(); // maps no longer wanted
        if (!pending &&
            GpuMaterial::texelsToUpload(*scene.assets, wrap, reuse, wanted) > g_backgroundTexels)
            pending = runningUpload(scene.assets, wrap, reuse, wanted);
        if (pending && !pending->finished())
            return success(); // drawing what there is meanwhile
        std::shared_ptr<GpuMaterial> made;
        if (pending) {
            Result<std::shared_ptr<GpuMaterial>> result = pending->result();
            if (result)
                made = std::move(*result);
            pending.reset();
        }
        if (!made && fitting) { // small: Renderer::draw prepares what the technique reads
            adopt(fitting);
            return success();
        }
        if (!made) { // small, or no context could share the views': here
            Result<std::unique_ptr<GpuMaterial>> created =
                GpuMaterial::create(*scene.assets, wrap, reuse);
            if (!created)
                return created.error();
            made = std::move(*created);
        }
        adopt(std::make_shared<Upload>(Upload{scene.assets, wrap, std::move(made)}));
        uploads.push_back(upload);
        return success();
    }

    // The techniques a frame of `scene` draws.
    static std::vector<Technique> techniques(const PreviewScene& scene) {
        std::vector<Technique> t{scene.material.technique};
        if (scene.overlays.wipe)
            t.push_back(scene.overlays.wipeTechnique);
        return t;
    }

    void adopt(std::shared_ptr<Upload> other) {
        upload = std::move(other);
        gpu = upload->gpu.get();
        pending.reset();
    }

    // The worker upload of `assets`, another view's if one is running.
    static std::shared_ptr<MapUpload>
    runningUpload(const std::shared_ptr<const MaterialAssets>& assets, WrapMode wrap,
                  const GpuMaterial* reuse, const std::vector<Technique>& wanted) {
        std::vector<std::weak_ptr<MapUpload>>& running = runningUploads();
        for (const std::weak_ptr<MapUpload>& weak : running) {
            std::shared_ptr<MapUpload> other = weak.lock();
            // Another view's, whatever its techniques: a derived map it does not prepare goes up
            // next, taking the rest over.
            if (other && other->assets() == assets && other->wrap() == wrap)
                return other;
        }
        auto started = std::make_shared<MapUpload>(assets, wrap, reuse, wanted);
        running.push_back(started);
        return started;
    }

    // Whether the maps drawn are not the scene's yet (a worker is uploading them).
    bool uploading() const { return pending != nullptr; }

    // Whether the maps there are can stand in for the scene's while they upload: never made to
    // bake or change their wrap (other views draw them too).
    bool canDrawMeanwhile(const PreviewScene& scene) const {
        return gpu && upload->wrap == scene.material.wrap &&
               std::ranges::all_of(techniques(scene), [&](Technique t) { return gpu->ready(t); });
    }

    std::optional<Measurement> measurement;

    // What the current pass of `m` draws with.
    std::pair<Material, DrawOptions> passDraw(const Measurement& m) const {
        DrawOptions o = options(m.scene);
        o.output = ShaderOutput::Surface;
        o.clear = true; // inside the box
        Material material = m.scene.material;
        // Every traced pass in the verify kernels, equal to the CPU's (the bench's): the view's
        // technique reads the footprint's level bilinearly, the surface its own error is
        // measured on (the production kernels' trilinear filter blends in the next level).
        if (m.pass == Measurement::Pass::Entry) {
            material.technique = Technique::None; // the surface's own uv, t = 0
            material.params = info(Technique::None).defaults;
        } else if (m.pass == Measurement::Pass::View) {
            o.kernels = KernelFlavour::Verify;
        } else {
            material.technique = Technique::Exact;
            material.params = info(Technique::Exact).defaults;
            o.kernels = KernelFlavour::Verify;
            if (m.pass == Measurement::Pass::FootprintExact)
                o.output = ShaderOutput::FootprintSurface;
        }
        return {material, o};
    }

    VariantKey passVariant(const Measurement& m) const {
        const auto [material, o] = passDraw(m);
        return renderer->variantFor(*gpu, material, o);
    }

    // Draws box `m.next` of the current pass (the target bound) and moves on.
    Status drawNextBox(Measurement& m) {
        QOpenGLFunctions* f = gl();
        if (m.next == 0) {
            f->glDisable(GL_SCISSOR_TEST);
            f->glClearColor(-1.0f, -1.0f, -1.0f, -1.0f);
            f->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        }
        const auto [material, o] = passDraw(m);
        drew({renderer->variantFor(*gpu, material, o)});
        const QRect& box = m.passBoxes()[m.next++];
        f->glEnable(GL_SCISSOR_TEST);
        // GL counts rows from the bottom.
        f->glScissor(box.x(), surfaceTarget->size().y - box.y() - box.height(), box.width(),
                     box.height());
        Status status = renderer->draw(*gpu, material, m.scene.view.camera, m.scene.view.light, o,
                                       surfaceTarget->size());
        f->glDisable(GL_SCISSOR_TEST);
        return status;
    }

    DrawOptions options(const PreviewScene& scene) const {
        DrawOptions o;
        o.mesh = scene.view.mesh;
        o.customMesh = scene.view.meshData;
        o.background = kBackground;
        o.environment = gpuEnvironment.get();
        o.exposure = scene.view.exposure;
        o.showEnvironment = scene.view.showEnvironment;
        return o;
    }
};

PreviewRenderer::~PreviewRenderer() = default;

Result<std::unique_ptr<PreviewRenderer>> PreviewRenderer::create() {
    Result<std::unique_ptr<Renderer>> renderer = Renderer::create(groupShaderCache());
    if (!renderer)
        return renderer.error();
    std::unique_ptr<PreviewRenderer> preview(new PreviewRenderer);
    preview->m_impl = std::make_unique<Impl>();
    preview->m_impl->renderer = std::move(*renderer);
    return preview;
}

// What a frame of `scene` shows: the background alone, or the scene (its maps synced).
Result<bool> PreviewRenderer::prepare(const PreviewScene& scene) {
    Impl& d = *m_impl;
    if (!scene.traceable || !scene.assets)
        return false;
    if (Status s = d.sync(scene); !s)
        return s.error();
    if (Status s = d.syncEnvironment(scene); !s)
        return s.error();
    return !d.uploading() || d.canDrawMeanwhile(scene);
}

Status PreviewRenderer::drawScene(const PreviewScene& scene, glm::ivec2 size, QRect rows) {
    Impl& d = *m_impl;
    QOpenGLFunctions* f = gl();
    // GL counts rows from the bottom.
    auto clip = [&](int x0, int x1) {
        const QRect r = rows.isEmpty() ? QRect(0, 0, size.x, size.y) : rows;
        f->glEnable(GL_SCISSOR_TEST);
        f->glScissor(x0, size.y - r.y() - r.height(), x1 - x0, r.height());
    };
    const DrawOptions options = d.options(scene);
    if (!rows.isEmpty())
        clip(0, size.x);
    Status s = d.renderer->draw(*d.gpu, scene.material, scene.view.camera, scene.view.light,
                                options, size);
    f->glDisable(GL_SCISSOR_TEST);
    if (!s)
        return s;
    d.lastKey = d.renderer->variantFor(*d.gpu, scene.material, options);
    if (scene.overlays.wipe) {
        // B on the right of the divider: the same view again, scissored.
        Material b = scene.material;
        b.technique = scene.overlays.wipeTechnique;
        b.params = info(b.technique).defaults;
        clip(static_cast<int>(scene.overlays.wipePosition * size.x), size.x);
        s = d.renderer->draw(*d.gpu, b, scene.view.camera, scene.view.light, options, size);
        f->glDisable(GL_SCISSOR_TEST);
    }
    // QPainter draws the overlays next, on the depth the mesh left: hand it a neutral state.
    f->glDisable(GL_DEPTH_TEST);
    f->glDisable(GL_CULL_FACE);
    return s;
}

namespace {
void clearToBackground(glm::ivec2 size) {
    QOpenGLFunctions* f = gl();
    f->glViewport(0, 0, size.x, size.y);
    f->glClearColor(kBackground.r, kBackground.g, kBackground.b, 1.0f);
    f->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}
} // namespace

Result<double> PreviewRenderer::draw(const PreviewScene& scene, QSize pixels, unsigned fbo) {
    const auto start = std::chrono::steady_clock::now();
    gl()->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    const glm::ivec2 size(pixels.width(), pixels.height());
    Result<bool> shows = prepare(scene);
    if (!shows)
        return shows.error();
    if (!*shows) {
        clearToBackground(size);
        return 0.0;
    }
    if (Status s = drawScene(scene, size, QRect()); !s)
        return s.error();
    gl()->glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

Result<FramePacer::Step> PreviewRenderer::drawStep(const PreviewScene& scene, std::uint64_t serial,
                                                   QSize pixels, unsigned fbo, double budgetMs) {
    const glm::ivec2 size(std::max(1, pixels.width()), std::max(1, pixels.height()));
    Result<bool> shows = prepare(scene);
    if (!shows)
        return shows.error();
    if (!*shows) {
        gl()->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        clearToBackground(size);
        m_pacer.forget(); // the maps drawn next cost what they cost
        return FramePacer::Step{true, 0.0, 0, false};
    }
    Impl& d = *m_impl;
    // A variant this context never drew waits while the user acts: its first draw would hold
    // the event loop (FramePacer::inputRecently). Meanwhile the view shows what it had.
    const DrawOptions options = d.options(scene);
    std::vector<VariantKey> keys{d.renderer->variantFor(*d.gpu, scene.material, options)};
    if (scene.overlays.wipe) {
        Material b = scene.material;
        b.technique = scene.overlays.wipeTechnique;
        b.params = info(b.technique).defaults;
        keys.push_back(d.renderer->variantFor(*d.gpu, b, options));
    }
    const bool waits = d.waitForInputPause(keys);
    if (waits && !d.shownOnce) {
        gl()->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        clearToBackground(size);
        return FramePacer::Step{false, 0.0, 0, false};
    }
    // What the cost per pixel depends on beyond the camera and the sliders.
    std::uint64_t key = kFnv1aOffset;
    auto mix = [&key](std::uint64_t v) { key = fnv1a(&v, sizeof v, key); };
    mix(static_cast<std::uint64_t>(scene.material.technique));
    mix(scene.overlays.wipe ? 1 + static_cast<std::uint64_t>(scene.overlays.wipeTechnique) : 0);
    mix(reinterpret_cast<std::uintptr_t>(d.gpu));
    mix(static_cast<std::uint64_t>(scene.view.mesh));
    mix(reinterpret_cast<std::uintptr_t>(scene.view.meshData.get()));
    mix(scene.view.showEnvironment ? 1 : 0);
    mix((std::uint64_t(size.x) << 32) | std::uint64_t(size.y));
    Result<FramePacer::Step> step =
        m_pacer.step(serial, key, size, fbo, waits ? 0.0 : budgetMs,
                     [&](glm::ivec2 at, QRect rows) { return drawScene(scene, at, rows); });
    if (step && !waits && budgetMs > 0.0)
        d.drew(keys);
    d.shownOnce = d.shownOnce || (step && step->complete);
    // A step may draw nothing (the frame is whole): QPainter still needs the neutral state the
    // measurement's passes do not leave.
    gl()->glDisable(GL_DEPTH_TEST);
    gl()->glDisable(GL_CULL_FACE);
    return step;
}

Status PreviewRenderer::beginMeasure(const PreviewScene& scene, QSize pixels, double frameMs) {
    Impl& d = *m_impl;
    d.measurement.reset();
    // The view's own size: marching techniques read the height level each pixel's footprint
    // asks for, so a smaller render would measure another picture.
    const glm::ivec2 size(std::max(1, pixels.width()), std::max(1, pixels.height()));
    if (!d.surfaceTarget || d.surfaceTarget->size() != size) {
        Result<RenderTarget> target = RenderTarget::create(size, TargetFormat::Rgba32F);
        if (!target)
            return target.error();
        d.surfaceTarget = std::move(*target);
    }
    // Every pixel for the heat map, else a stratified sample of boxes, enough for a p99.
    d.measurement.emplace();
    d.measurement->scene = scene;
    d.measurement->frameMs = frameMs;
    d.measurement->boxes =
        scene.overlays.heatMap ? bands(size.x, size.y) : sampleBoxes(size.x, size.y);
    d.measurement->whole = {QRect(0, 0, size.x, size.y)};
    return success();
}

std::optional<Result<PreviewStats>> PreviewRenderer::measureStep(double sliceMs) {
    Impl& d = *m_impl;
    PreviewStats stats;
    if (!d.measurement)
        return stats;
    Measurement& m = *d.measurement;
    stats.frameMs = m.frameMs;
    auto done = [&](Result<PreviewStats> result) {
        d.measurement.reset();
        return std::optional<Result<PreviewStats>>(std::move(result));
    };
    const PreviewScene& scene = m.scene;
    if (!scene.traceable || !scene.assets || scene.assets->height.empty()) {
        m_heatMap = {};
        return done(stats);
    }
    if (Status s = d.sync(scene); !s)
        return done(s.error());
    if (d.uploading())
        return done(stats); // not valid: measured once the scene's maps are up
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::duration d) {
        return std::chrono::duration<double, std::milli>(d).count();
    };
    const auto start = Clock::now();
    QOpenGLFunctions* f = gl();
    d.surfaceTarget->bind();
    for (;;) {
        // A pass on a variant this context never drew waits while the user acts, as frames do.
        d.measureWaits = m.next == 0 && d.waitForInputPause({d.passVariant(m)});
        if (d.measureWaits) {
            f->glBindFramebuffer(GL_FRAMEBUFFER, 0);
            return std::nullopt;
        }
        const auto boxStart = Clock::now();
        if (Status s = d.drawNextBox(m); !s) {
            f->glBindFramebuffer(GL_FRAMEBUFFER, 0);
            return done(s.error());
        }
        if (m.next == m.passBoxes().size()) {
            Image image = d.surfaceTarget->read();
            if (m.pass == Measurement::Pass::Exact) {
                f->glBindFramebuffer(GL_FRAMEBUFFER, 0);
                const int mapWidth = scene.assets->height.width,
                          mapHeight = scene.assets->height.height;
                const VisibleRegion region(m.entry, mapWidth, mapHeight);
                ReferenceSurfaces references;
                references.exact = &image;
                references.footprintExact = &m.footprint;
                references.entry = &m.entry;
                const SurfaceErrors errors =
                    compareSurfaces(m.hits, references, mapWidth, mapHeight, &region);
                stats = statsOf(errors);
                stats.frameMs = m.frameMs;
                m_heatMap = scene.overlays.heatMap ? heatMapImage(errors, scene.overlays.heatMode)
                                                   : QImage();
                if (m_keepSurfaces)
                    m_surfaces = {m.entry, m.hits, m.footprint, std::move(image)};
                return done(stats);
            }
            if (m.pass == Measurement::Pass::Entry) {
                m.entry = std::move(image);
                m.pass = Measurement::Pass::View;
            } else if (m.pass == Measurement::Pass::View) {
                m.hits = std::move(image);
                m.pass = Measurement::Pass::FootprintExact;
            } else {
                m.footprint = std::move(image);
                m.pass = Measurement::Pass::Exact;
            }
            m.next = 0;
            d.surfaceTarget->bind();
        }
        f->glFinish(); // what the slice has cost so far
        m.boxMs = std::max(m.boxMs, ms(Clock::now() - boxStart));
        // At least a box a step; no box that would take the step past its slice.
        if (ms(Clock::now() - start) + m.boxMs > sliceMs)
            break;
    }
    f->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return std::nullopt;
}

double PreviewRenderer::measureBoxMs() const {
    return m_impl->measurement ? m_impl->measurement->boxMs : 0.0;
}

void PreviewRenderer::cancelMeasure() {
    m_impl->measurement.reset();
}

bool PreviewRenderer::measuring() const {
    return m_impl->measurement.has_value();
}

bool PreviewRenderer::measureWaitsForInput() const {
    return m_impl->measureWaits;
}

bool PreviewRenderer::uploading() const {
    return m_impl->uploading();
}

bool PreviewRenderer::mapsArrived() const {
    return m_impl->pending && m_impl->pending->finished();
}

void PreviewRenderer::waitForMaps() {
    if (m_impl->pending)
        m_impl->pending->wait();
}

void PreviewRenderer::setBackgroundUploadTexels(std::size_t texels) {
    g_backgroundTexels = texels;
}

const GpuMaterial* PreviewRenderer::gpuMaterial() const {
    return m_impl->gpu;
}

const ShaderCache& PreviewRenderer::shaders() const {
    return m_impl->renderer->shaders();
}

std::optional<float> PreviewRenderer::uniformValue(const std::string& name) {
    Impl& d = *m_impl;
    if (!d.lastKey)
        return std::nullopt;
    Result<const ShaderProgram*> program = d.renderer->shaders().program(*d.lastKey);
    if (!program)
        return std::nullopt;
    const int location = (*program)->location(name);
    if (location < 0)
        return std::nullopt;
    auto* f = QOpenGLContext::currentContext()->extraFunctions();
    // Room for a mat4: GL writes every component of the uniform; the first is returned. It
    // converts int uniforms too.
    float values[16] = {};
    f->glGetUniformfv((*program)->id(), location, values);
    return values[0];
}

} // namespace px::studio

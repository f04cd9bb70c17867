#include "jobs/MapUpload.h"

#include "jobs/SharedGlContext.h"
#include "parallax/render/GpuMaterial.h" // parallax-render

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>
#include <atomic>

namespace px::studio {

namespace {

std::atomic<int> g_completed{0};

// Its own thread: an upload never waits behind a bake or the bench on Qt's global pool.
QThreadPool& uploadPool() {
    static QThreadPool pool;
    pool.setMaxThreadCount(1);
    return pool;
}

} // namespace

struct MapUpload::Made {
    std::shared_ptr<GpuMaterial> gpu;
    std::string error;
};

MapUpload::MapUpload(std::shared_ptr<const MaterialAssets> assets, WrapMode wrap,
                     const GpuMaterial* previous, std::vector<Technique> techniques)
    : m_assets(std::move(assets)), m_wrap(wrap), m_techniques(std::move(techniques)) {
    // A copy shares previous's textures and CPU maps; the worker reads only the copy.
    std::shared_ptr<GpuMaterial> snapshot =
        previous ? std::make_shared<GpuMaterial>(*previous) : nullptr;
    std::shared_ptr<QOffscreenSurface> surface = workerSurface();
    m_future = QtConcurrent::run(&uploadPool(), [assets = m_assets, wrap, snapshot, surface,
                                                 techniques = m_techniques]() mutable {
        auto made = std::make_shared<Made>();
        Result<std::shared_ptr<QOpenGLContext>> context = sharedViewportContext(surface);
        if (!context) {
            made->error = context.error().message;
            return made;
        }
        Result<std::unique_ptr<GpuMaterial>> gpu =
            GpuMaterial::create(*assets, wrap, snapshot.get());
        snapshot.reset(); // textures only it held go with this context current
        for (Technique t : techniques) {
            if (!gpu)
                break;
            if (Status prepared = (*gpu)->prepare(t); !prepared)
                gpu = prepared.error();
        }
        // Finished before a view's context reads the textures.
        (*context)->functions()->glFinish();
        if (gpu)
            made->gpu = std::move(*gpu);
        else
            made->error = gpu.error().message;
        ++g_completed;
        return made;
    });
}

MapUpload::~MapUpload() {
    m_future.waitForFinished(); // the worker reads this upload's maps
}

Result<std::shared_ptr<GpuMaterial>> MapUpload::result() const {
    const std::shared_ptr<Made> made = m_future.result();
    if (!made->gpu)
        return Error{made->error};
    return made->gpu;
}

int MapUpload::completed() {
    return g_completed.load();
}

} // namespace px::studio

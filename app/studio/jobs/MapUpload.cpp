#include "jobs/MapUpload.h"

#include "jobs/BackgroundPriority.h"
#include "jobs/SharedGlContext.h"
#include "parallax/render/GpuMaterial.h" // parallax-render

#include <QCoreApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>

namespace px::studio {

namespace {

std::atomic<int> g_completed{0};
std::atomic<int> g_discarded{0};
std::atomic<int> g_skipped{0};

// Tests hold the workers at their start, to destroy an upload while it runs.
std::mutex g_holdMutex;
std::condition_variable g_holdChanged;
bool g_held = false;

void waitWhileHeld() {
    // At most 30 s: a test that waits on the worker fails instead of hanging.
    std::unique_lock lock(g_holdMutex);
    g_holdChanged.wait_for(lock, std::chrono::seconds(30), [] { return !g_held; });
}

void finishUploads();

// Its own thread: an upload never waits behind a bake or the bench on Qt's global pool.
QThreadPool& uploadPool() {
    static QThreadPool& pool = []() -> QThreadPool& {
        static QThreadPool p;
        p.setMaxThreadCount(1);
        // An upload whose view went first runs on: it must end while the GUI (and the views'
        // share context) still exists, not in the pool's static destructor.
        qAddPostRoutine(finishUploads);
        return p;
    }();
    return pool;
}

void finishUploads() {
    uploadPool().waitForDone();
}

} // namespace

struct MapUpload::Made {
    std::shared_ptr<GpuMaterial> gpu;
    std::string error;
};

// Between the upload and its worker: whether nobody wants the result any more, and whether the
// worker has handed one over (its textures are then the GUI thread's to release).
struct MapUpload::Handover {
    std::mutex mutex;
    bool abandoned = false;
    bool delivered = false;
    bool isAbandoned() {
        std::lock_guard lock(mutex);
        return abandoned;
    }
};

MapUpload::MapUpload(std::shared_ptr<const MaterialAssets> assets, WrapMode wrap,
                     const GpuMaterial* previous, std::vector<Technique> techniques)
    : m_assets(std::move(assets)), m_wrap(wrap), m_techniques(std::move(techniques)),
      m_handover(std::make_shared<Handover>()) {
    // A copy shares previous's textures and CPU maps; the worker reads only the copy.
    std::shared_ptr<GpuMaterial> snapshot =
        previous ? std::make_shared<GpuMaterial>(*previous) : nullptr;
    std::shared_ptr<QOffscreenSurface> surface = workerSurface();
    m_future = QtConcurrent::run(&uploadPool(), [assets = m_assets, wrap, snapshot, surface,
                                                 techniques = m_techniques,
                                                 handover = m_handover]() mutable {
        waitWhileHeld();
        auto made = std::make_shared<Made>();
        // Nobody wants it any more (the view went, or its maps changed while it waited behind
        // another upload on the one thread): the next upload is not kept waiting for it.
        if (handover->isAbandoned()) {
            ++g_skipped;
            return made;
        }
        // Below the GUI thread, as bakes are; the context's driver threads (llvmpipe's), made
        // next on this thread, inherit it.
        lowerThisThreadsPriority();
        Result<std::shared_ptr<QOpenGLContext>> context = sharedViewportContext(surface);
        if (!context) {
            made->error = context.error().message;
            return made;
        }
        Result<std::unique_ptr<GpuMaterial>> gpu =
            GpuMaterial::create(*assets, wrap, snapshot.get());
        snapshot.reset(); // textures only it held go with this context current
        for (Technique t : techniques) {
            if (!gpu || handover->isAbandoned()) // between the maps, as soon as it is known
                break;
            if (Status prepared = (*gpu)->prepare(t); !prepared)
                gpu = prepared.error();
        }
        // Finished before a view's context reads the textures.
        (*context)->functions()->glFinish();
        std::lock_guard lock(handover->mutex);
        if (handover->abandoned) { // its textures go here, with this context current
            ++g_discarded;
            return made;
        }
        if (gpu)
            made->gpu = std::move(*gpu);
        else
            made->error = gpu.error().message;
        handover->delivered = true;
        ++g_completed;
        return made;
    });
}

MapUpload::~MapUpload() {
    // Never waits for the upload itself (1.1-1.4 s at 8192² on llvmpipe): the worker holds what it
    // reads and releases what it made. Only a result it has already handed over is released here,
    // on the GUI thread, where a view's context is current (not wherever the future ends).
    bool delivered = false;
    {
        std::lock_guard lock(m_handover->mutex);
        m_handover->abandoned = true;
        delivered = m_handover->delivered;
    }
    if (delivered) {
        m_future.waitForFinished(); // the worker is returning: moments
        m_future.result()->gpu.reset();
    }
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

int MapUpload::discarded() {
    return g_discarded.load();
}

int MapUpload::skipped() {
    return g_skipped.load();
}

void MapUpload::holdWorkers(bool held) {
    {
        std::lock_guard lock(g_holdMutex);
        g_held = held;
    }
    g_holdChanged.notify_all();
}

} // namespace px::studio

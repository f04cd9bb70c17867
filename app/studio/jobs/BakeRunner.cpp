#include "jobs/BakeRunner.h"

#include "jobs/BackgroundPriority.h"
#include "jobs/GpuConeBake.h"
#include "jobs/SharedGlContext.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/ConeMapFinish.h"

#include <QMetaObject>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>
#include <chrono>
#include <cmath>

namespace px::studio {

QString bakeTitle(BakeKind kind) {
    switch (kind) {
    case BakeKind::Normal:
        return QObject::tr("normal map");
    case BakeKind::Cone:
        return QObject::tr("cone map");
    case BakeKind::RelaxedCone:
        return QObject::tr("relaxed cone map");
    case BakeKind::Occlusion:
        return QObject::tr("ambient occlusion map");
    case BakeKind::BentNormal:
        return QObject::tr("bent normal map");
    }
    return {};
}

QString bakeDevice(const BakeOutcome& outcome) {
    const QString where =
        outcome.gpu.isEmpty() ? QObject::tr("on the CPU") : QObject::tr("on the GPU");
    return outcome.deviceWhy.isEmpty() ? where
                                       : QObject::tr("%1 (%2)").arg(where, outcome.deviceWhy);
}

namespace {

BakeOutcome runBake(const BakeRequest& request, const BakeControl& control,
                    const std::shared_ptr<QOffscreenSurface>& surface) {
    lowerThisThreadsPriority(); // the runner's own thread: bakes only
    BakeOutcome outcome;
    outcome.request = request;
    outcome.threadNice = thisThreadsNice();
    const auto start = std::chrono::steady_clock::now();
    const HeightField& field = request.source->height;
    if (request.kind == BakeKind::Normal) {
        Result<Image> normal = bakeNormalMap(field, request.normal, control);
        if (normal)
            outcome.normal = std::move(*normal);
        else if (isCancelled(normal.error()))
            outcome.cancelled = true;
        else
            outcome.error = QString::fromStdString(normal.error().message);
    } else if (request.kind == BakeKind::Occlusion || request.kind == BakeKind::BentNormal) {
        const OcclusionOutputs outputs = request.kind == BakeKind::Occlusion
                                             ? OcclusionOutputs::AmbientOcclusion
                                             : OcclusionOutputs::Both;
        Result<OcclusionMaps> maps = bakeOcclusion(field, request.occlusion, outputs, control);
        if (maps) {
            outcome.occlusion = std::move(maps->occlusion);
            outcome.bentNormals = std::move(maps->bentNormals);
        } else if (isCancelled(maps.error())) {
            outcome.cancelled = true;
        } else {
            outcome.error = QString::fromStdString(maps.error().message);
        }
    } else {
        const ConeKind kind =
            request.kind == BakeKind::Cone ? ConeKind::Conservative : ConeKind::Relaxed;
        outcome.deviceWhy = request.device.why;
        Result<ConeMap> cone = Error{"not baked"};
        if (request.device.gpu) {
            QString gpu;
            cone = bakeConeOnGpu(field, request.wrap, kind, control, surface, &gpu);
            if (cone)
                outcome.gpu = gpu;
            else if (!isCancelled(cone.error())) // no GPU context after all: the same map here
                outcome.deviceWhy = QObject::tr("the GPU failed: %1")
                                        .arg(QString::fromStdString(cone.error().message));
        }
        if (!request.device.gpu || (!cone && !isCancelled(cone.error())))
            cone = bakeConeMap(field, request.wrap, kind, control);
        if (cone) {
            // 16 bits, a 16-bit file's precision (never wider): with a 16-bit height the GPU
            // then holds the cone map in RG16, half of RG32F (an 8192² map: 256 MiB less).
            quantiseDown(*cone, 65535);
            outcome.cone = std::move(*cone);
        } else if (isCancelled(cone.error()))
            outcome.cancelled = true;
        else
            outcome.error = QString::fromStdString(cone.error().message);
    }
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return outcome;
}

} // namespace

BakeRunner::BakeRunner(QObject* parent)
    : QObject(parent), m_arena(std::make_unique<BackgroundArena>()) {
    m_pool.setMaxThreadCount(1); // one bake at a time, in the order asked
    connect(&m_watcher, &QFutureWatcher<BakeOutcome>::finished, this, &BakeRunner::done);
}

BakeRunner::~BakeRunner() {
    m_queue.clear();
    if (m_cancel)
        m_cancel->store(true);
    m_watcher.waitForFinished();
}

std::optional<BakeKind> BakeRunner::current() const {
    if (!m_running || !m_runningRequest)
        return std::nullopt;
    return m_runningRequest->kind;
}

void BakeRunner::start(const BakeRequest& request) {
    m_queue.push_back(request);
    m_queue.back().asked = std::chrono::steady_clock::now();
    if (!m_running)
        next();
}

void BakeRunner::cancel() {
    m_queue.clear();
    if (m_cancel && m_runningRequest && !m_cancel->exchange(true))
        emit cancelling(m_runningRequest->kind);
}

void BakeRunner::next() {
    if (m_queue.empty()) {
        emit idle();
        return;
    }
    m_runningRequest = m_queue.front();
    m_queue.pop_front();
    m_running = true;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    const BakeKind kind = m_runningRequest->kind;
    emit started(kind);
    emit progress(kind, 0.0);

    // Progress comes from the worker: post whole percents only, never paint from there.
    auto lastPercent = std::make_shared<std::atomic<int>>(-1);
    QPointer<BakeRunner> self(this);
    BakeControl control;
    control.cancel = m_cancel.get();
    control.progress = [self, kind, lastPercent](float fraction) {
        const int percent = static_cast<int>(std::floor(fraction * 100.0f));
        if (lastPercent->exchange(percent) == percent)
            return;
        QMetaObject::invokeMethod(
            self.data(),
            [self, kind, fraction] {
                if (self)
                    emit self->progress(kind, fraction);
            },
            Qt::QueuedConnection);
    };
    BakeRequest request = *m_runningRequest;
    // The cancel flag lives as long as the job: the job holds its own reference.
    std::shared_ptr<std::atomic<bool>> flag = m_cancel;
    // Cone bakes go where BakeDevice.h says; on the GPU in a context sharing the viewports' (a
    // surface for the worker's is made here, on the GUI thread, as Qt requires).
    std::shared_ptr<QOffscreenSurface> surface;
    if (kind == BakeKind::Cone || kind == BakeKind::RelaxedCone) {
        const bool shared = QOpenGLContext::globalShareContext() != nullptr;
        request.device = chooseBakeDevice(m_preference, m_renderer, shared);
        if (request.device.gpu)
            surface = workerSurface();
    }
    BackgroundArena* arena = m_arena.get(); // outlives the job: ~BakeRunner waits for it
    m_watcher.setFuture(QtConcurrent::run(&m_pool, [request, control, flag, arena, surface] {
        BakeOutcome outcome;
        // The bakers' loops in the arena; the GPU's context on the runner's own thread.
        arena->execute([&] { outcome = runBake(request, control, surface); });
        return outcome;
    }));
}

void BakeRunner::done() {
    BakeOutcome outcome = m_watcher.result();
    m_running = false;
    m_runningRequest.reset();
    emit finished(outcome);
    next();
}

} // namespace px::studio

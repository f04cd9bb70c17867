#pragma once
// Runs the bakers (normal, cone, relaxed cone, occlusion) on a worker thread, one at a time in the
// order asked, with progress and cancellation: the UI never waits for a bake. Cone bakes run on the
// device BakeDevice.h chooses: the GPU (GpuConeBake.h) where it is a GPU and a context can share
// the viewports', the CPU where the renderer is a software rasteriser, or the artist's choice. The
// result comes back on the GUI thread together with the maps it was baked from, so the caller can
// tell whether the height map changed meanwhile.

#include "jobs/BakeDevice.h"
#include "parallax/bake/ConeMap.h"
#include "parallax/bake/NormalMapBaker.h"
#include "parallax/bake/OcclusionBaker.h"
#include "parallax/material/MaterialAssets.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <atomic>
#include <chrono>
#include <deque>
#include <memory>
#include <utility>

namespace px::studio {

class BackgroundArena;

// Occlusion fills the occlusion map; BentNormal bakes the bent normals (and the occlusion map
// from the same horizons) for saving to a file: the material has no slot for them.
enum class BakeKind { Normal, Cone, RelaxedCone, Occlusion, BentNormal };
// "normal map", "cone map", "relaxed cone map", "ambient occlusion map", "bent normal map"
QString bakeTitle(BakeKind kind);

struct BakeRequest {
    BakeKind kind = BakeKind::Cone;
    // When it was asked for (BakeRunner::start): the wait a user sees runs from here.
    std::chrono::steady_clock::time_point asked;
    std::shared_ptr<const MaterialAssets> source; // its height map is baked
    WrapMode wrap = WrapMode::Repeat;
    NormalBakeOptions normal;       // for BakeKind::Normal
    BakeDeviceChoice device;        // cone bakes: where, and why (BakeRunner::start decides)
    OcclusionBakeOptions occlusion; // for BakeKind::Occlusion and BentNormal
};

struct BakeOutcome {
    BakeRequest request;
    Image normal;      // BakeKind::Normal
    ConeMap cone;      // BakeKind::Cone and RelaxedCone
    Image occlusion;   // BakeKind::Occlusion and BentNormal
    Image bentNormals; // BakeKind::BentNormal
    QString error;     // empty on success
    bool cancelled = false;
    double seconds = 0.0; // the bake itself, on its thread
    int threadNice = 0;   // the bake's thread's nice value while it baked (BackgroundPriority.h)
    QString gpu;          // cone bakes: the GL renderer that baked them, empty if the CPU did
    QString deviceWhy;    // cone bakes: why there (BakeDeviceChoice::why, or the GPU's failure)
};

// Where a bake ran and why, as its status line says it: "on the CPU (the GPU, llvmpipe ..., is a
// software rasteriser: the CPU bakes faster)", "on the GPU (NVIDIA ...: a GPU bakes faster than
// the CPU)"; a normal map's "on the CPU".
QString bakeDevice(const BakeOutcome& outcome);

class BakeRunner : public QObject {
    Q_OBJECT
public:
    explicit BakeRunner(QObject* parent = nullptr);
    ~BakeRunner() override; // cancels and waits: no worker outlives the runner

    void start(const BakeRequest& request); // queued behind a running bake
    // Where cone bakes started from now on run (the settings' choice at first).
    void setDevicePreference(BakeDevicePreference preference) { m_preference = preference; }
    // The GL renderer the viewports run on (GL_RENDERER): a software rasteriser bakes on the CPU.
    void setRenderer(QString renderer) { m_renderer = std::move(renderer); }
    BakeDevicePreference devicePreference() const { return m_preference; }
    void cancel(); // the running bake and every queued one
    bool isBusy() const { return m_running || !m_queue.empty(); }
    // The bake running now, if any.
    std::optional<BakeKind> current() const;

signals:
    void started(px::studio::BakeKind kind);
    // A cancel was asked for while `kind` was baking; finished() follows once it has stopped.
    void cancelling(px::studio::BakeKind kind);
    void progress(px::studio::BakeKind kind, double fraction);
    void finished(const px::studio::BakeOutcome& outcome);
    void idle();

private:
    void next();
    void done();

    BakeDevicePreference m_preference = savedBakeDevicePreference();
    QString m_renderer;
    std::deque<BakeRequest> m_queue;
    std::optional<BakeRequest> m_runningRequest;
    bool m_running = false;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    // A thread and a TBB arena of the bakes' own, both below the GUI: the threads that run loads
    // and exports (Qt's global pool, TBB's default arena) keep their priority.
    QThreadPool m_pool;
    std::unique_ptr<BackgroundArena> m_arena;
    QFutureWatcher<BakeOutcome> m_watcher;
};

} // namespace px::studio

#pragma once
// A material's maps uploaded on a worker thread, on a context sharing the viewports' textures
// (SharedGlContext.h). llvmpipe takes 1.1-1.4 s in glTexSubImage2D for an 8192² height map: on
// the GUI thread that froze the window. The views draw the maps they have until it is done.

#include "parallax/Result.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/trace/Technique.h"

#include <QFuture>
#include <memory>
#include <vector>

namespace px {
class GpuMaterial;
struct MaterialAssets;
} // namespace px

namespace px::studio {

class MapUpload {
public:
    // Call on the GUI thread. Takes over `previous`'s textures where the maps are the same
    // (GpuMaterial::create; a snapshot of it is made here, so the views may go on using it), and
    // prepares the derived maps `techniques` read.
    MapUpload(std::shared_ptr<const MaterialAssets> assets, WrapMode wrap,
              const GpuMaterial* previous, std::vector<Technique> techniques);
    ~MapUpload(); // does not wait for the worker
    MapUpload(const MapUpload&) = delete;
    MapUpload& operator=(const MapUpload&) = delete;

    const std::shared_ptr<const MaterialAssets>& assets() const { return m_assets; }
    const std::vector<Technique>& techniques() const { return m_techniques; }
    WrapMode wrap() const { return m_wrap; }
    bool finished() const { return m_future.isFinished(); }
    void wait() { m_future.waitForFinished(); }
    // Once finished: the material, or why there is none (no context could share the views').
    Result<std::shared_ptr<GpuMaterial>> result() const;

    // Uploads finished on a worker so far, those whose upload was destroyed first (their
    // textures released on the worker), and those destroyed before the worker began them (it
    // then skips them: the one upload thread is not kept from the next upload) (tests).
    static int completed();
    static int discarded();
    static int skipped();
    // Tests: workers wait at their start while held.
    static void holdWorkers(bool held);

private:
    struct Made;
    struct Handover;
    std::shared_ptr<const MaterialAssets> m_assets;
    WrapMode m_wrap;
    std::vector<Technique> m_techniques;
    std::shared_ptr<Handover> m_handover;
    QFuture<std::shared_ptr<Made>> m_future;
};

} // namespace px::studio

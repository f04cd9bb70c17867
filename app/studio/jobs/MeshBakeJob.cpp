#include "jobs/MeshBakeJob.h"

#include <filesystem>

namespace px::studio {

Result<SharedBakeMesh> readBakeMesh(const std::string& path, MeshUp up,
                                    std::atomic<float>* progress, const std::atomic<bool>* cancel) {
    BakeMeshLoadOptions load;
    load.up = up;
    load.progress = [progress, cancel](float done) {
        if (progress != nullptr)
            progress->store(done, std::memory_order_relaxed);
        return cancel == nullptr || !cancel->load(std::memory_order_relaxed);
    };
    Result<BakeMesh> mesh = loadBakeMesh(path, load);
    if (!mesh)
        return mesh.error();
    return SharedBakeMesh(std::make_shared<const BakeMesh>(std::move(*mesh)));
}

Result<MeshBakeResult> bakeMeshMaps(const SharedBakeMesh& mesh, const MeshBakeOptions& options,
                                    std::atomic<float>* progress, const std::atomic<bool>* cancel) {
    BakeControl control;
    control.progress = [progress](float done) {
        if (progress != nullptr)
            progress->store(done, std::memory_order_relaxed);
    };
    control.cancel = cancel;
    return bakeFromMesh(*mesh, options, control);
}

DocumentState meshBakeState(const DocumentState& current, const std::string& meshFile,
                            const MeshBakeOptions& options, MeshBakeResult baked) {
    DocumentState next;
    next.views = current.views;
    Material& m = next.material;
    m = current.material;
    m.name = std::filesystem::path(meshFile).stem().string();
    m.maps = {};
    m.heightIsDepth = false;
    m.heightRange.reset();
    m.heightDerivedFrom.clear();
    m.heightChannel = HeightChannel::Red;
    m.surface = {};
    m.heightScale = static_cast<float>(baked.heightScale);
    m.wrap = options.wrap;
    m.normalGreen = options.green;
    auto assets = std::make_shared<MaterialAssets>();
    if (!baked.height.empty()) {
        HeightField field;
        field.width = baked.height.width;
        field.height = baked.height.height;
        field.texels = std::move(baked.height.pixels);
        assets->height = std::move(field);
        next.setUnsaved(MapKind::Height, true);
    }
    if (!baked.normal.empty()) {
        assets->normal = std::move(baked.normal);
        next.setUnsaved(MapKind::Normal, true);
    }
    if (!baked.occlusion.empty()) {
        assets->ao = std::move(baked.occlusion);
        next.setUnsaved(MapKind::Ao, true);
    }
    m.normalSource = !assets->normal.empty()   ? NormalSource::Map
                     : !assets->height.empty() ? NormalSource::HeightCentral
                                               : NormalSource::None;
    if (assets->height.empty())
        m.technique = assets->normal.empty() ? Technique::None : Technique::Normal;
    else if (m.technique == Technique::None || m.technique == Technique::Normal)
        m.technique = Technique::Pom;
    next.assets = std::move(assets);
    return next;
}

} // namespace px::studio

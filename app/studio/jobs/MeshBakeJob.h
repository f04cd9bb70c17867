#pragma once
// Bake ▸ From Mesh…: a sculpted tile read and baked into height, normal and occlusion maps
// (core/meshbake) on a worker, and the result made the document's new material: the maps in
// memory (saved beside the material), the height scale that keeps the relief true, the tile's
// wrap mode. docs/editor.md, "Baking from a mesh".

#include "model/DocumentState.h"
#include "parallax/Result.h"
#include "parallax/meshbake/MeshBake.h"

#include <atomic>
#include <memory>
#include <string>

namespace px::studio {

// A mesh read for baking (shared by the dialog, which shows its bounds, and the bake).
using SharedBakeMesh = std::shared_ptr<const BakeMesh>;

// Reads the mesh; `progress` (0..1) is written as Assimp reads, `cancel` stops it.
Result<SharedBakeMesh> readBakeMesh(const std::string& path, MeshUp up,
                                    std::atomic<float>* progress = nullptr,
                                    const std::atomic<bool>* cancel = nullptr);

// Bakes `options.maps` from the mesh; progress and cancel as above.
Result<MeshBakeResult> bakeMeshMaps(const SharedBakeMesh& mesh, const MeshBakeOptions& options,
                                    std::atomic<float>* progress = nullptr,
                                    const std::atomic<bool>* cancel = nullptr);

// The new material: named after the mesh, the baked maps in memory (unsaved), height scale and
// wrap from the bake, the normal map as the normal source, the occlusion map; other settings
// (technique, lighting) and the viewports' techniques are kept from `current`.
DocumentState meshBakeState(const DocumentState& current, const std::string& meshFile,
                            const MeshBakeOptions& options, MeshBakeResult baked);

} // namespace px::studio

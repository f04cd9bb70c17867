#pragma once
// Everything an undo step restores: the material, the maps in memory, and each viewport's
// technique and quality. Maps are shared and immutable, so a snapshot costs a few pointers.

#include "parallax/bake/NormalMapBaker.h"
#include "parallax/material/MapKind.h"
#include "parallax/material/Material.h"
#include "parallax/material/MaterialAssets.h"

#include <array>
#include <memory>
#include <optional>

namespace px::studio {

inline constexpr int kMaxViewports = 4;

// How the normal map in memory was baked here: it describes the surface at that height scale.
struct NormalBake {
    float heightScale = 0.05f;
    NormalFilter filter = NormalFilter::Sobel;
};

// How the occlusion map in memory was baked here (parallax/bake/OcclusionBaker.h): it describes
// the surface at that height scale and wrap.
struct OcclusionBake {
    float heightScale = 0.05f;
    WrapMode wrap = WrapMode::Repeat;
    double distance = 0.0; // horizontal uv; +inf: unlimited
    int directions = 0;    // azimuths the bake used
};

// What one viewport traces with. Viewport 1's is the material's own (technique and params).
struct ViewQuality {
    Technique technique = Technique::Pom;
    TraceParams params = info(Technique::Pom).defaults;
};

bool sameParams(const TraceParams& a, const TraceParams& b);
bool operator==(const ViewQuality& a, const ViewQuality& b);

// Viewports 2..4 start on techniques worth comparing with the material's: relief (march and
// refine), pyramid (exact, no pre-process to wait for) and the exact reference.
std::array<ViewQuality, kMaxViewports> defaultComparisonViews();

struct DocumentState {
    Material material;
    // Never null. Members are empty for maps the material does not have in memory.
    std::shared_ptr<const MaterialAssets> assets = std::make_shared<MaterialAssets>();
    // Maps held in memory with no file yet (the generated sample, bakes): written beside the
    // material when it is saved.
    std::array<bool, kAllMapKinds.size()> unsaved{};
    // Set while the normal map is one baked here (not a loaded file).
    std::optional<NormalBake> normalBake;
    // Set while the occlusion map is one baked here.
    std::optional<OcclusionBake> occlusionBake;
    // Viewports 2..4 (index 0 is unused: viewport 1 shows the material's technique).
    std::array<ViewQuality, kMaxViewports> views = defaultComparisonViews();

    ViewQuality view(int index) const;
    void setView(int index, const ViewQuality& quality);

    bool isUnsaved(MapKind kind) const { return unsaved[static_cast<std::size_t>(kind)]; }
    void setUnsaved(MapKind kind, bool value) { unsaved[static_cast<std::size_t>(kind)] = value; }
    bool anyUnsaved() const;
    // A map is present when it is in memory (loaded or made here).
    bool hasMap(MapKind kind) const;
    // Whether viewport techniques that need this technique's maps can run now.
    bool canTrace(Technique technique) const;
};

} // namespace px::studio

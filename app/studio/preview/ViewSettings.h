#pragma once
// How a viewport looks at the material: the renderer's orbit camera, directional light and mesh,
// and the overlays. View state, not part of the material: not saved with it and not undone (like
// a camera in any 3D tool).

#include "parallax/light/EnvironmentLighting.h"
#include "parallax/render/Camera.h" // parallax-render: OrbitCamera, DirectionalLight
#include "parallax/render/Mesh.h"   // parallax-render: MeshKind
#include "parallax/trace/Technique.h"
#include "preview/HeatMode.h"

#include <QString>
#include <memory>

namespace px::studio {

using px::DirectionalLight;
using px::MeshKind;
using px::OrbitCamera;

// The camera a viewport starts with: the plane seen from above at an angle, filling the view.
OrbitCamera defaultCamera();

// Shared by every viewport while views are linked.
struct SharedView {
    OrbitCamera camera = defaultCamera();
    DirectionalLight light;
    MeshKind mesh = MeshKind::Plane;
    // A loaded mesh file drawn instead of `mesh` (MeshLoader.h), and its path; null: `mesh`.
    std::shared_ptr<const MeshData> meshData;
    QString meshFile;
    int meshUvSet = 0;  // the file's uv set read
    int meshUvSets = 1; // how many it has
    // Image-based light (docs/lighting.md), prefiltered; null: the light's ambient fill. Its
    // name is "sky" (the built-in one, its sun at `skySun`, made again when the light moves:
    // SkyFollower.h) or the file.
    std::shared_ptr<const PrefilteredEnvironment> environment;
    QString environmentName;
    glm::vec3 skySun{0.0f};
    float exposure = 0.0f;       // stops, under an environment
    bool showEnvironment = true; // behind the mesh, under an environment
};

// `camera` from the same angles, framing `view`'s mesh in a view of `aspect` (width / height): the
// plane at defaultCamera()'s distance, filling the view; any other mesh as close as it stays
// whole seen from these angles, with a margin (never farther than its bounding sphere needs).
OrbitCamera framed(OrbitCamera camera, const SharedView& view, float aspect);
// The radius of the sphere about the origin holding `view`'s mesh.
float meshRadius(const SharedView& view);

struct ViewOverlays {
    bool heatMap = false;
    HeatMode heatMode = HeatMode::Technique;    // which error the heat map shows
    bool wipe = false;                          // A/B wipe on
    Technique wipeTechnique = Technique::Exact; // the right-hand side (B)
    float wipePosition = 0.5f;                  // divider, 0..1 across the view
};

} // namespace px::studio

#pragma once
// parallax-cli bake height|normal|ao --mesh FILE: a sculpted tile baked into maps on Embree
// (core/meshbake, docs/conventions.md §8). The bake command's half for meshes: its options, the
// checks of which options apply, and the run.

#include "parallax/Result.h"
#include "parallax/image/ImageFile.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace px::cli {

struct MeshBakeCli {
    std::string mesh;
    std::string tile; // x0,y0,x1,y1; empty: the mesh's XY bounds
    std::string up = "z";
    std::string range; // z0,z1; empty: the range of the hits
    std::string size = "1024";
    int samples = 1;
    int rays = 64;
    std::string material;
    std::string root; // --mesh-root: the folder the mesh's references must lie under

    // Adds --mesh, --mesh-root, --tile, --up, --range, --size, --samples, --rays, --material
    // (--distance is the bake command's, shared with the height-map occlusion bakes).
    void addTo(CLI::App& command);
    // Whether this is a bake from a mesh (--mesh given, or height, which only meshes bake).
    bool asked(const std::string& kind) const;
    // An error naming the first mesh-only option given to a bake from a height map.
    Status checkNotGiven(const std::string& kind, const CLI::App& command) const;
};

// What the bake command's common options say for a mesh bake.
struct MeshBakeOutput {
    std::string kind; // height, normal or ao
    std::string wrap;
    std::string green;
    PixelFormat format = PixelFormat::UInt16;
    std::string out;
    double distance = 0; // ao: --distance (shared with the height-map occlusion bakes), or inf
};

int runMeshBake(const MeshBakeCli& m, const MeshBakeOutput& o, const CLI::App& command);

} // namespace px::cli

#pragma once
// Baking a sculpted tile into height, normal and occlusion maps on Intel Embree, with the tile's
// periodicity built in (docs/conventions.md §8, docs/bakers.md):
//
//   Result<BakeMesh> mesh = loadBakeMesh("rock.ply");
//   MeshBakeOptions o;
//   o.tile = defaultTile(*mesh);
//   o.width = o.height = 2048;
//   o.maps = {true, true, false};
//   Result<MeshBakeResult> maps = bakeFromMesh(*mesh, o, control);
//
// The tile is a rectangle of the mesh's XY plane seen from +Z: image right = +X, image top = +Y.
// Texel (i, j) samples the point under its centre, or K x K sub-samples box-averaged. Height is
// the first hit of a ray from above, mapped to [0, 1] by the range; normal is the shading normal
// at that hit in the tile's tangent space; occlusion is the cosine-weighted visibility of the
// hemisphere over that normal (docs/conventions.md §7's quantity). `repeat` rays also see the
// mesh's eight copies shifted by whole tiles.

#include "parallax/Result.h"
#include "parallax/bake/BakeControl.h"
#include "parallax/bake/NormalGreen.h"
#include "parallax/heightfield/WrapMode.h"
#include "parallax/image/Image.h"
#include "parallax/meshbake/BakeMesh.h"

#include <cstdint>
#include <limits>
#include <optional>

namespace px {

struct BakeTile {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
};

// The mesh's XY bounds.
BakeTile defaultTile(const BakeMesh& mesh);

struct HeightRangeZ {
    double z0 = 0, z1 = 1;
};

struct MeshBakeMaps {
    bool height = true;
    bool normal = false;
    bool occlusion = false;
};

struct MeshBakeOptions {
    BakeTile tile;
    int width = 1024, height = 1024;
    int samples = 1; // K: K x K sub-samples per texel, box-averaged
    WrapMode wrap = WrapMode::Repeat;
    // Heights z0..z1 map to 0..1; unset: the range of the hits. A hit outside a given range is an
    // error (it would be clamped).
    std::optional<HeightRangeZ> range;
    MeshBakeMaps maps;
    NormalGreen green = NormalGreen::OpenGL;
    int rays = 64; // occlusion rays per texel, shared among its sub-samples
    // Occlusion rays end here (mesh units). With repeat they see the 3 x 3 copies, so the reach is
    // one tile beyond the tile whatever the distance.
    double distance = std::numeric_limits<double>::infinity();
    std::uint32_t seed = 0; // rotates the occlusion directions per texel
};

struct MeshBakeResult {
    Image height;               // 1 channel, [0, 1] (empty if not asked for)
    Image normal;               // 3 channels, n * 0.5 + 0.5, green as asked
    Image occlusion;            // 1 channel, 1 = unoccluded
    HeightRangeZ range;         // the range the heights were mapped by
    double heightScale = 0;     // (z1 - z0) / tile width: uv units (docs/conventions.md §2)
    std::int64_t samples = 0;   // rays from above: texels x K^2
    std::int64_t misses = 0;    // of those, the ones that met nothing (height = range minimum)
    std::int64_t overhangs = 0; // hits with more surface below them
    int copies = 1;             // instances of the mesh the rays saw
};

// Checks the options against the mesh: a tile of positive size holding geometry, sizes, samples,
// rays, distance, range. Errors name `mesh.file` where the mesh is the problem.
Status checkMeshBake(const BakeMesh& mesh, const MeshBakeOptions& options);

// Cancel and progress are honoured between slices of rows (BakeControl.h).
Result<MeshBakeResult> bakeFromMesh(const BakeMesh& mesh, const MeshBakeOptions& options,
                                    const BakeControl& control = {});

} // namespace px

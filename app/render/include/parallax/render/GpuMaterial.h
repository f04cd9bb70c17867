#pragma once
// A material's maps on the GPU. The height, albedo, normal and occlusion/roughness/metallic maps
// are uploaded when it is created; the derived maps a technique reads (cone map, relaxed cone map,
// max-mip pyramid) only when prepare() is called for that technique, baked from the height map if
// the material has no file for them. So a `pom` view never bakes a cone map and a `cone` view
// never builds a pyramid. An editor bakes in the background and makes a new GpuMaterial from the
// assets with the baked maps, taking the unchanged textures over from the old one (`previous`).

#include "parallax/bake/ConeMap.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/material/MaterialAssets.h"
#include "parallax/render/GlObjects.h"
#include "parallax/render/ShaderProgram.h"

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace px {

class GpuMaterial {
public:
    // Uploads every map present in `assets` (an empty member is an absent map). Fails, naming
    // the map, when one is larger than the GL allows or malformed (a normal map without 3
    // channels). Cone maps in `assets` are kept (CPU side) and uploaded when a technique asks.
    // With `previous` (same wrap), a map whose texels are the very ones `previous` uploaded (the
    // same shared buffer, as after a bake or an undo: not an equal copy) takes its texture over
    // instead of uploading it again; the two then share it until both are gone, so it must be
    // used in the same GL share group, and setWrap() on one changes the other's sampling.
    static Result<std::unique_ptr<GpuMaterial>> create(const MaterialAssets& assets, WrapMode wrap,
                                                       const GpuMaterial* previous = nullptr);
    // A copy shares the textures and CPU maps (an editor hands a snapshot to a worker as
    // `previous`); it costs pointers.
    // The texels create() and then prepare() for `techniques` would upload (not take over from
    // `previous`): an editor uploads big ones on a worker.
    static std::size_t texelsToUpload(const MaterialAssets& assets, WrapMode wrap,
                                      const GpuMaterial* previous,
                                      std::span<const Technique> techniques = {});

    // Makes sure the maps `technique` reads are on the GPU: bakes (synchronously) and uploads the
    // cone map, the relaxed cone map or the pyramid if needed. Cheap when they are there.
    Status prepare(Technique technique);
    // What prepare() would still have to bake for `technique`.
    bool ready(Technique technique) const;

    // The wrap mode changes sampler state and invalidates the derived maps (baked per wrap mode).
    void setWrap(WrapMode wrap);
    WrapMode wrap() const { return m_wrap; }

    bool hasHeight() const { return static_cast<bool>(m_height); }
    bool hasAlbedo() const { return static_cast<bool>(m_albedo); }
    bool hasNormalMap() const { return static_cast<bool>(m_normal); }
    bool hasSurfaceMap() const { return static_cast<bool>(m_orm); }
    // Which maps the surface texture holds (the others' channels hold 1: SurfaceFactors.h).
    bool hasRoughnessMap() const { return !m_roughnessMap.empty(); }
    bool hasMetallicMap() const { return !m_metallicMap.empty(); }
    bool heightIs16Bit() const { return m_height16; }
    // The cone texture of `kind` is RG16 (heights and cones on the 16-bit grid), not RG32F.
    bool coneMapIs16Bit(ConeKind kind) const {
        return kind == ConeKind::Conservative ? m_cone16 : m_relaxed16;
    }
    const HeightField& heightField() const { return m_field; }
    // Bakes performed so far (cone, relaxed cone, pyramid), for tests and the status bar.
    int bakeCount() const { return m_bakes; }
    // Textures uploaded by this material (not taken over from `previous`), for tests.
    int uploadCount() const { return m_uploads; }

    // Binds every texture present to its unit and sets the map-derived uniforms (height max,
    // pyramid rows) on `program`.
    void bind(const ShaderProgram& program) const;

private:
    using Texture = std::shared_ptr<const gl::Object>;
    // Which maps of `assets` are the very ones `previous` holds (see create()).
    struct Kept {
        bool height = false, albedo = false, normal = false, orm = false;
        bool cone = false, relaxedCone = false, pyramid = false;
    };
    GpuMaterial() = default;
    static Kept kept(const MaterialAssets& assets, const GpuMaterial* previous);
    Status uploadMaps(const MaterialAssets& assets, const GpuMaterial* previous);

    WrapMode m_wrap = WrapMode::Repeat;
    HeightField m_field;
    // The maps the textures were made from: their texels tell whether a new material's are the
    // same (SharedTexels::sharesWith).
    Image m_albedoMap, m_normalMap, m_aoMap, m_roughnessMap, m_metallicMap;
    float m_heightMax = 1.0f;
    bool m_height16 = false;
    Texture m_height, m_albedo, m_normal, m_orm;
    // Derived maps: CPU copy (given or baked) and GPU texture.
    std::optional<ConeMap> m_coneCpu, m_relaxedCpu;
    std::shared_ptr<const MaxMipPyramid> m_pyramidCpu;
    Texture m_cone, m_relaxed, m_atlas;
    bool m_cone16 = false, m_relaxed16 = false;
    std::vector<int> m_atlasRows;
    int m_atlasTop = 0;
    int m_bakes = 0;
    int m_uploads = 0;
};

} // namespace px

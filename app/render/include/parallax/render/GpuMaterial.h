#pragma once
// A material's maps on the GPU. The height, albedo, normal and occlusion/roughness/metallic maps
// are uploaded when it is created; the derived maps a technique reads (cone map, relaxed cone map,
// max-mip pyramid) only when prepare() is called for that technique, baked from the height map if
// the material has no file for them. So a `pom` view never bakes a cone map and a `cone` view
// never builds a pyramid. An editor can bake in the background and hand the result over with
// setConeMap()/setPyramid() instead (these must run on the GL thread).

#include "parallax/bake/ConeMap.h"
#include "parallax/bake/MaxMipPyramid.h"
#include "parallax/material/MaterialAssets.h"
#include "parallax/render/GlObjects.h"
#include "parallax/render/ShaderProgram.h"

#include <memory>
#include <optional>
#include <vector>

namespace px {

class GpuMaterial {
public:
    // Uploads every map present in `assets` (an empty member is an absent map). Fails, naming
    // the map, when one is larger than the GL allows or malformed (a normal map without 3
    // channels). Cone maps in `assets` are kept (CPU side) and uploaded when a technique asks.
    static Result<std::unique_ptr<GpuMaterial>> create(const MaterialAssets& assets, WrapMode wrap);

    // Makes sure the maps `technique` reads are on the GPU: bakes (synchronously) and uploads the
    // cone map, the relaxed cone map or the pyramid if needed. Cheap when they are there.
    Status prepare(Technique technique);
    // What prepare() would still have to bake for `technique`.
    bool ready(Technique technique) const;

    void setConeMap(const ConeMap& cones); // its kind says which one
    void setPyramid(const MaxMipPyramid& pyramid);
    // The wrap mode changes sampler state and invalidates the derived maps (baked per wrap mode).
    void setWrap(WrapMode wrap);
    WrapMode wrap() const { return m_wrap; }

    bool hasHeight() const { return static_cast<bool>(m_height); }
    bool hasAlbedo() const { return static_cast<bool>(m_albedo); }
    bool hasNormalMap() const { return static_cast<bool>(m_normal); }
    bool hasSurfaceMap() const { return static_cast<bool>(m_orm); }
    bool heightIs16Bit() const { return m_height16; }
    const HeightField& heightField() const { return m_field; }
    // Bakes performed so far (cone, relaxed cone, pyramid), for tests and the status bar.
    int bakeCount() const { return m_bakes; }

    // Binds every texture present to its unit and sets the map-derived uniforms (height max,
    // pyramid rows) on `program`.
    void bind(const ShaderProgram& program) const;

private:
    GpuMaterial() = default;

    WrapMode m_wrap = WrapMode::Repeat;
    HeightField m_field;
    float m_heightMax = 1.0f;
    bool m_height16 = false;
    gl::Object m_height, m_albedo, m_normal, m_orm;
    // Derived maps: CPU copy (given or baked) and GPU texture.
    std::optional<ConeMap> m_coneCpu, m_relaxedCpu;
    std::optional<MaxMipPyramid> m_pyramidCpu;
    gl::Object m_cone, m_relaxed, m_atlas;
    std::vector<int> m_atlasRows;
    int m_atlasTop = 0;
    int m_bakes = 0;
};

} // namespace px
